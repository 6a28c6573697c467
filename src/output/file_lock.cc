#include "output/file_lock.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/file.h>
#include <unistd.h>

namespace DiskImpact
{
  void
  FileLock::open(const std::string &filename)
  {
    descriptor = ::open(filename.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor < 0)
      throw std::runtime_error("cannot write " + filename + ": " +
                               std::strerror(errno));
  }

  FileLock::FileLock(const std::string &filename)
  {
    open(filename);
    while (::flock(descriptor, LOCK_EX) != 0)
      if (errno != EINTR)
        {
          const int error = errno;
          ::close(descriptor);
          throw std::runtime_error("cannot lock " + filename + ": " +
                                   std::strerror(error));
        }
  }

  FileLock::FileLock(const std::string &filename, bool &held)
  {
    open(filename);
    held = ::flock(descriptor, LOCK_EX | LOCK_NB) == 0;
    if (!held)
      {
        const int error = errno;
        ::close(descriptor);
        descriptor = -1;
        if (error != EWOULDBLOCK)
          throw std::runtime_error("cannot lock " + filename + ": " +
                                   std::strerror(error));
      }
  }

  FileLock::~FileLock()
  {
    if (descriptor >= 0)
      ::close(descriptor);
  }
} // namespace DiskImpact
