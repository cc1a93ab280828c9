#pragma once
// Input files are opened only when they are regular files: opening a FIFO blocks until a
// writer appears (a run that hangs at start), and a directory or device is never a mesh or deck.
#include <string>

namespace peridot {

// "" if `path` names a regular file this process can read; otherwise the reason in words, with
// the operating system's reason where there is one ("No such file or directory (paths are
// relative to the working directory /home/u/run)").
std::string whyNotReadableFile(const std::string& path);

}  // namespace peridot
