#include "output/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace DiskImpact
{
  namespace
  {
    /// Throw "cannot write FILE: CAUSE" for the C library's errno @p error,
    /// after removing @p temporary (if not empty).
    [[noreturn]] void
    fail(const std::string &filename,
         const std::string &temporary,
         const int          error)
    {
      if (!temporary.empty())
        std::remove(temporary.c_str());
      throw std::runtime_error("cannot write " + filename + ": " +
                               std::strerror(error));
    }
  } // namespace

  void
  write_atomically(const std::string &filename, const std::string &contents)
  {
    const std::string temporary = filename + ".tmp";
    const int         descriptor =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (descriptor < 0)
      fail(filename, "", errno);
    const char *data = contents.data();
    std::size_t left = contents.size();
    while (left > 0)
      {
        const ssize_t written = ::write(descriptor, data, left);
        if (written < 0 && errno == EINTR)
          continue;
        if (written <= 0)
          {
            const int error = written < 0 ? errno : ENOSPC;
            ::close(descriptor);
            fail(filename, temporary, error);
          }
        data += written;
        left -= written;
      }
    // A full disk may show only when the data reach it.
    if (::fsync(descriptor) != 0 && errno != EINVAL && errno != EROFS)
      {
        const int error = errno;
        ::close(descriptor);
        fail(filename, temporary, error);
      }
    if (::close(descriptor) != 0)
      fail(filename, temporary, errno);
    if (std::rename(temporary.c_str(), filename.c_str()) != 0)
      fail(filename, temporary, errno);
  }

  void
  write_atomically(const std::string                         &filename,
                   const std::function<void(std::ostream &)> &write)
  {
    std::ostringstream contents;
    write(contents);
    write_atomically(filename, contents.str());
  }
} // namespace DiskImpact
