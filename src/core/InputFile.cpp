#include "core/InputFile.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace peridot {

std::string whyNotReadableFile(const std::string& path) {
  if (path.empty()) return "the file name is empty";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    std::string why = std::strerror(errno);
    if (errno == ENOENT && !path.empty() && path[0] != '/') {
      std::error_code ec;
      const auto cwd = std::filesystem::current_path(ec);
      why += " (relative paths are taken from the working directory";
      if (!ec) why += " " + cwd.string();
      why += ")";
    }
    return why;
  }
  if (S_ISDIR(st.st_mode)) return "it is a directory";
  if (!S_ISREG(st.st_mode)) {
    return S_ISFIFO(st.st_mode) ? "it is a FIFO (named pipe), not a regular file"
                                : "it is not a regular file (a device or socket)";
  }
  if (::access(path.c_str(), R_OK) != 0) return std::strerror(errno);
  return "";
}

}  // namespace peridot
