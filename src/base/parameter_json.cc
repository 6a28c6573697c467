#include "base/parameter_json.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cstdio>
#include <sstream>

namespace DiskImpact
{
  namespace
  {
    /**
     * The length of the valid UTF-8 character at @p text[i], or 0 if the
     * byte there does not start one (RFC 3629: no overlong forms, no
     * surrogates, nothing above U+10FFFF).
     */
    std::size_t
    utf8_character_length(const std::string &text, const std::size_t i)
    {
      const auto byte = [&](const std::size_t k) {
        return static_cast<unsigned char>(text[k]);
      };
      const unsigned char lead = byte(i);
      if (lead < 0x80)
        return 1;
      std::size_t   length;
      unsigned char low = 0x80, high = 0xBF; // range of the second byte
      if (lead >= 0xC2 && lead <= 0xDF)
        length = 2;
      else if (lead >= 0xE0 && lead <= 0xEF)
        {
          length = 3;
          low    = lead == 0xE0 ? 0xA0 : 0x80;
          high   = lead == 0xED ? 0x9F : 0xBF;
        }
      else if (lead >= 0xF0 && lead <= 0xF4)
        {
          length = 4;
          low    = lead == 0xF0 ? 0x90 : 0x80;
          high   = lead == 0xF4 ? 0x8F : 0xBF;
        }
      else
        return 0;
      if (i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high)
        return 0;
      for (std::size_t k = 2; k < length; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF)
          return 0;
      return length;
    }

    /// Remove every alias node (one with a child "alias") below @p tree.
    void
    remove_aliases(boost::property_tree::ptree &tree)
    {
      for (auto child = tree.begin(); child != tree.end();)
        if (child->second.count("alias") > 0)
          child = tree.erase(child);
        else
          {
            remove_aliases(child->second);
            ++child;
          }
    }
  } // namespace

  std::string
  escape_invalid_utf8_for_json(const std::string &text)
  {
    std::string valid;
    valid.reserve(text.size());
    for (std::size_t i = 0; i < text.size();)
      if (const std::size_t length = utf8_character_length(text, i))
        {
          valid.append(text, i, length);
          i += length;
        }
      else
        {
          char escaped[8];
          std::snprintf(escaped,
                        sizeof(escaped),
                        "\\\\x%02X",
                        static_cast<unsigned char>(text[i]));
          valid += escaped;
          ++i;
        }
    return valid;
  }

  std::string
  parameters_as_json(const dealii::ParameterHandler             &prm,
                     const dealii::ParameterHandler::OutputStyle style)
  {
    std::ostringstream printed;
    prm.print_parameters(printed, style);
    std::istringstream valid(escape_invalid_utf8_for_json(printed.str()));
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(valid, tree);
    remove_aliases(tree);
    std::ostringstream json;
    boost::property_tree::write_json(json, tree);
    return json.str();
  }
} // namespace DiskImpact
