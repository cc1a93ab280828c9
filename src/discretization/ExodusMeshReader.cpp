#include "discretization/ExodusMeshReader.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/Error.hpp"
#include "core/InputFile.hpp"
#include "discretization/DistributedExodusReader.hpp"

namespace peridot {

namespace {

// Room for the longest name netCDF allows (NC_MAX_NAME) plus the terminator.
constexpr std::size_t kNameBufferSize = NC_MAX_NAME + 1;

// The number of bytes a classic-format netCDF file (CDF-1, CDF-2 or CDF-5, which is what Exodus
// writes) must have to hold all the data its header declares, or -1 for other formats (netCDF-4's
// HDF5 layer detects truncation itself) and headers this cannot follow. Needed because the netCDF
// library reads the missing tail of a truncated classic file as zeros, without an error.
// kBrokenHeader when a length in the header itself runs past the end of the file: netCDF would
// then allocate and copy what the damaged length says (a flipped bit took it 15 s and gigabytes),
// so such a file is refused before netCDF opens it.
constexpr long long kBrokenHeader = -2;
class ClassicHeader {
 public:
  explicit ClassicHeader(const std::string& fileName) : in_(fileName, std::ios::binary) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(fileName, ec);
    fileSize_ = ec ? 0 : static_cast<unsigned long long>(size);
  }

  long long dataEnd() {
    const long long end = walk();
    return broken_ ? kBrokenHeader : end;
  }

 private:
  long long walk() {
    char magic[4] = {0, 0, 0, 0};
    if (!in_.read(magic, 4) || magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F') return -1;
    const int version = magic[3];
    if (version != 1 && version != 2 && version != 5) return -1;
    sizeBytes_ = version == 5 ? 8 : 4;
    const int offsetBytes = version == 1 ? 4 : 8;
    const unsigned long long numRecords = read(sizeBytes_);
    const bool streaming = sizeBytes_ == 4 && numRecords == 0xFFFFFFFFull;

    std::vector<unsigned long long> dimLength;
    unsigned long long count = listLength(kDimensionTag);
    for (unsigned long long d = 0; d < count && ok_; ++d) {
      skipName();
      dimLength.push_back(read(sizeBytes_));
    }
    skipAttributes();
    count = listLength(kVariableTag);
    long long end = 0;
    unsigned long long recordSize = 0;
    std::vector<std::pair<unsigned long long, unsigned long long>> records;  // begin, size
    for (unsigned long long v = 0; v < count && ok_; ++v) {
      skipName();
      const unsigned long long numDims = read(sizeBytes_);
      if (numDims > 1024) return -1;
      bool isRecord = false;
      unsigned long long size = 1;
      for (unsigned long long d = 0; d < numDims && ok_; ++d) {
        const unsigned long long dim = read(sizeBytes_);
        if (dim >= dimLength.size()) return -1;
        if (d == 0 && dimLength[dim] == 0) {
          isRecord = true;
        } else {
          size *= dimLength[dim];
        }
      }
      skipAttributes();
      size *= typeSize(static_cast<int>(read(4)));
      read(sizeBytes_);  // vsize: recomputed above, the stored one saturates for huge variables
      const unsigned long long begin = read(offsetBytes);
      if (isRecord) {
        records.emplace_back(begin, size);
        recordSize += (size + 3) / 4 * 4;
      } else {
        end = std::max(end, static_cast<long long>(begin + size));
      }
    }
    if (!ok_) return -1;
    if (records.size() == 1) recordSize = records[0].second;  // a lone record variable: no padding
    if (!streaming && numRecords > 0) {
      for (const auto& [begin, size] : records) {
        end = std::max(end, static_cast<long long>(begin + (numRecords - 1) * recordSize + size));
      }
    }
    return end;
  }

  static constexpr unsigned long long kDimensionTag = 0x0A;
  static constexpr unsigned long long kVariableTag = 0x0B;
  static constexpr unsigned long long kAttributeTag = 0x0C;

  static unsigned long long typeSize(int type) {
    switch (type) {
      case NC_BYTE:
      case NC_CHAR:
      case NC_UBYTE:
        return 1;
      case NC_SHORT:
      case NC_USHORT:
        return 2;
      case NC_INT:
      case NC_FLOAT:
      case NC_UINT:
        return 4;
      default:
        return 8;
    }
  }

  // Big-endian unsigned integer of the given width; clears ok_ at the end of the file.
  unsigned long long read(int bytes) {
    unsigned char buffer[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    if (!ok_ || !in_.read(reinterpret_cast<char*>(buffer), bytes)) {
      ok_ = false;
      return 0;
    }
    unsigned long long value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | buffer[i];
    return value;
  }
  // Whether `bytes` more fit between the read position and the end of the file (seekg past the
  // end does not fail by itself).
  bool fits(unsigned long long bytes) {
    const auto at = in_.tellg();
    if (at < 0 || bytes > fileSize_ || static_cast<unsigned long long>(at) > fileSize_ - bytes) {
      broken_ = true;
      ok_ = false;
    }
    return ok_;
  }
  void skip(unsigned long long bytes) {
    if (bytes > fileSize_) bytes = fileSize_ + 1;  // no overflow in the rounding below
    if (ok_ && fits((bytes + 3) / 4 * 4) &&
        !in_.seekg(static_cast<std::streamoff>((bytes + 3) / 4 * 4), std::ios::cur)) {
      ok_ = false;
    }
  }
  void skipName() { skip(read(sizeBytes_)); }
  // Element count of a tagged list (0 for an absent one); clears ok_ on an unexpected tag.
  unsigned long long listLength(unsigned long long tag) {
    const unsigned long long found = read(4);
    const unsigned long long count = read(sizeBytes_);
    if (found != tag && !(found == 0 && count == 0)) ok_ = false;
    // Every element takes at least 4 bytes of the header.
    if (ok_ && count > fileSize_ / 4) {
      broken_ = true;
      ok_ = false;
    }
    return ok_ ? count : 0;
  }
  void skipAttributes() {
    const unsigned long long count = listLength(kAttributeTag);
    for (unsigned long long a = 0; a < count && ok_; ++a) {
      skipName();
      const int type = static_cast<int>(read(4));
      const unsigned long long n = read(sizeBytes_);
      skip(n > fileSize_ ? fileSize_ + 1 : n * typeSize(type));
    }
  }

  std::ifstream in_;
  unsigned long long fileSize_ = 0;
  int sizeBytes_ = 4;
  bool ok_ = true;
  bool broken_ = false;
};

// Why fileName cannot be read as an Exodus file, or "" when it looks fine.
std::string openProblem(const std::string& fileName) {
  std::error_code ec;
  const std::string notFile = whyNotReadableFile(fileName);
  if (!notFile.empty()) return notFile;
  std::FILE* f = std::fopen(fileName.c_str(), "rb");
  if (f == nullptr) return std::strerror(errno);
  std::fclose(f);
  const long long needed = ClassicHeader(fileName).dataEnd();
  if (needed == kBrokenHeader) {
    return "not a readable Exodus (netCDF) file, or a truncated or corrupt one (a length in its "
           "netCDF header runs past the end of the file)";
  }
  int ncid = -1;
  const int status = nc_open(fileName.c_str(), NC_NOWRITE, &ncid);
  if (status != NC_NOERR) {
    return std::string("not a readable Exodus (netCDF) file, or a truncated or corrupt one (") +
           nc_strerror(status) + ")";
  }
  nc_close(ncid);
  const auto size = std::filesystem::file_size(fileName, ec);
  if (!ec && needed > 0 && static_cast<long long>(size) < needed) {
    return "the file is truncated (" + std::to_string(size) + " bytes where its header needs " +
           std::to_string(needed) + ")";
  }
  return "";
}

}  // namespace

std::string exodusLastError() {
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  std::string text = message != nullptr ? message : "";
  if (function != nullptr && *function != '\0') text = std::string(function) + ": " + text;
  // Codes beyond +-1000 are the Exodus library's own; the others are netCDF or errno codes.
  if (code != 0 && code > -1000 && code < 1000) {
    text += std::string(text.empty() ? "" : "; ") + nc_strerror(code);
  }
  return text.empty() ? "(no details)" : text;
}

ExodusInputFile::ExodusInputFile(const std::string& fileName, const std::string& kind,
                                 const std::string& deckPath) {
  const auto failOpen = [&](const std::string& reason) {
    throw InputError(deckPath, "cannot open Exodus " + kind + " \"" + fileName + "\": " + reason);
  };
  const std::string problem = openProblem(fileName);
  if (!problem.empty()) failOpen(problem);
  int cpuWordSize = sizeof(double);
  int ioWordSize = 0;
  float version = 0.0f;
  id_ = ex_open(fileName.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  if (id_ < 0) {
    // A netCDF signature with a header that does not read is almost always a cut-off file.
    std::ifstream in(fileName, std::ios::binary);
    char magic[3] = {0, 0, 0};
    in.read(magic, 3);
    if (in && magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F') {
      failOpen("the file is truncated or damaged: its netCDF header cannot be read (" +
               exodusLastError() + ")");
    }
    failOpen("not a readable Exodus file (" + exodusLastError() + ")");
  }
  ex_set_int64_status(id_, EX_ALL_INT64_API);
  // Read names as long as the file stores them (the library default is 32 characters).
  const int64_t longestName = ex_inquire_int(id_, EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (longestName > 32 && longestName < static_cast<int64_t>(kNameBufferSize)) {
    ex_set_max_name_length(id_, static_cast<int>(longestName));
  }
}

ExodusInputFile::~ExodusInputFile() {
  if (id_ >= 0) ex_close(id_);
}

PointCloud readExodusMesh(const std::string& fileName, const std::string& deckPath,
                          double thickness) {
  // One reader: the distributed one, with this rank as the only one.
  return readExodusMeshShare(fileName, deckPath, thickness, MPI_COMM_SELF);
}

}  // namespace peridot
