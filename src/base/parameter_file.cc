#include "base/parameter_file.h"

#include "base/input_error.h"
#include "base/renamed_entries.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /** A line of the expanded parameter text and where it comes from. */
    struct SourceLine
    {
      std::filesystem::path file;
      unsigned int          number;
      std::string           text;
    };

    /**
     * The file named by the 'include FILE' line @p line of @p including, or
     * an empty path if @p line is no include line. FILE is taken relative
     * to the working directory if it exists there, else relative to the
     * including file's directory.
     */
    std::filesystem::path
    included_file(const std::string           &line,
                  const std::filesystem::path &including)
    {
      const auto start = line.find_first_not_of(" \t");
      if (start == std::string::npos ||
          (line.compare(start, 8, "include ") != 0 &&
           line.compare(start, 8, "INCLUDE ") != 0))
        return {};
      std::string name = line.substr(start + 8);
      name             = name.substr(0, name.find('#'));
      name             = Utilities::trim(name);
      require(!name.empty(),
              "in parameter file '" + including.string() +
                "': 'include' names no file");
      std::filesystem::path path(name);
      if (!std::filesystem::exists(path) && path.is_relative())
        path = including.parent_path() / name;
      return path;
    }

    /**
     * Append the lines of parameter file @p filename to @p text, each
     * 'include FILE' line replaced by FILE's lines (recursively), and the
     * origin of each line to @p origins. A missing file and an include
     * cycle, which would recurse without end, throw an InputError.
     * @p chain: the files including this one.
     */
    void
    expand_includes(const std::filesystem::path        &filename,
                    std::vector<std::filesystem::path> &chain,
                    std::string                        &text,
                    std::vector<SourceLine>            &origins)
    {
      namespace fs = std::filesystem;
      require(fs::is_regular_file(filename),
              "parameter file '" + filename.string() + "' " +
                (fs::is_directory(filename) ? "is a directory" :
                                              "does not exist") +
                (chain.empty() ?
                   "" :
                   " (included from '" + chain.back().string() + "')"));
      const fs::path canonical = fs::canonical(filename);
      require(std::find(chain.begin(), chain.end(), canonical) == chain.end(),
              "parameter file '" + filename.string() +
                "' includes itself (directly or through other files)");
      chain.push_back(canonical);
      std::ifstream in(filename);
      std::string   line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          const fs::path included = included_file(line, filename);
          if (!included.empty())
            {
              expand_includes(included, chain, text, origins);
              continue;
            }
          text += line + '\n';
          origins.push_back({filename, number, line});
        }
      chain.pop_back();
    }

    /**
     * Throw an InputError if parameter file @p filename has no statement: an
     * empty file would run the defaults, almost surely not what was meant.
     */
    void
    require_a_statement(const std::string &filename)
    {
      std::ifstream    in(filename);
      const std::regex statement(
        "^\\s*(set|SET|include|INCLUDE|subsection)\\s");
      std::string line;
      while (std::getline(in, line))
        if (std::regex_search(line, statement))
          return;
      throw InputError("parameter file '" + filename +
                       "' sets nothing (empty, or comments only): give at "
                       "least 'set Task = ...'");
    }

    /**
     * deal.II's message for a line it could not parse, folded into one
     * line, with the line number of the expanded text replaced by the file
     * and line of @p origins it comes from, and the line quoted (deal.II
     * only numbers it).
     */
    std::string
    one_line_message(const ExceptionBase           &error,
                     const std::vector<SourceLine> &origins)
    {
      std::ostringstream info;
      error.print_info(info);
      std::string message =
        std::regex_replace(info.str(), std::regex("\\s+"), " ");
      message = std::regex_replace(message, std::regex("^ | $"), "");
      std::smatch where;
      if (!std::regex_search(message,
                             where,
                             std::regex("Line <([0-9]+)> of file <[^>]*>")))
        return message;
      const unsigned long n = std::stoul(where[1].str());
      if (n < 1 || n > origins.size())
        return message;
      const SourceLine &origin = origins[n - 1];
      return where.prefix().str() + "Line <" + std::to_string(origin.number) +
             "> of file <" + origin.file.string() + ">" + where.suffix().str() +
             " (the line reads '" + Utilities::trim(origin.text) + "')";
    }

    /**
     * One notice per line of @p origins that sets an entry by its old name
     * (renamed_entries()): "FILE:LINE: 'OLD' (subsection S) is now called
     * 'NEW'". Subsections are followed by their 'subsection' and 'end'
     * lines, as deal.II reads them.
     */
    std::vector<std::string>
    renamed_entry_notices(const std::vector<SourceLine> &origins)
    {
      const std::regex subsection("^\\s*(subsection|SUBSECTION)\\s+(.*?)\\s*$");
      const std::regex end("^\\s*(end|END)\\s*$");
      const std::regex set("^\\s*(set|SET)\\s+(.*?)\\s*=");
      std::vector<std::string> path;
      std::vector<std::string> notices;
      for (const SourceLine &line : origins)
        {
          const std::string text = line.text.substr(0, line.text.find('#'));
          std::smatch       match;
          if (std::regex_search(text, match, subsection))
            path.push_back(match[2].str());
          else if (std::regex_search(text, end) && !path.empty())
            path.pop_back();
          else if (std::regex_search(text, match, set))
            {
              std::string joined;
              for (const std::string &name : path)
                joined += (joined.empty() ? "" : "/") + name;
              for (const RenamedEntry &entry : renamed_entries())
                if (entry.subsection == joined &&
                    entry.old_name == match[2].str())
                  notices.push_back(line.file.string() + ":" +
                                    std::to_string(line.number) + ": '" +
                                    entry.old_name + "' (subsection " +
                                    entry.subsection + ") is now called '" +
                                    entry.new_name + "'");
            }
        }
      return notices;
    }
  } // namespace

  std::vector<std::string>
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    std::vector<std::filesystem::path> chain;
    std::string                        text;
    std::vector<SourceLine>            origins;
    expand_includes(filename, chain, text, origins);
    require_a_statement(filename);
    try
      {
        // deal.II reads 'include' relative to the working directory only;
        // the expanded text also finds a file beside the including one.
        std::istringstream expanded(text);
        prm.parse_input(expanded, filename);
      }
    catch (const ExceptionBase &e)
      {
        throw InputError("in parameter file '" + filename +
                         "': " + one_line_message(e, origins));
      }
    return renamed_entry_notices(origins);
  }
} // namespace DiskImpact
