#include "restart/Checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"

namespace peridot {

namespace {

constexpr char kMagic[8] = {'P', 'D', 'T', 'C', 'K', 'P', 'T', '1'};
constexpr char kEndMagic[8] = {'P', 'D', 'T', 'C', 'K', 'E', 'N', 'D'};
constexpr std::uint32_t kVersion = 1;
constexpr std::int64_t kHeaderBytes = 4096;
constexpr std::size_t kChunk = std::size_t(1) << 30;  // MPI counts are int

struct Header {
  char magic[8];
  std::uint32_t version, headerBytes;
  std::uint64_t deckHash, meshHash;
  std::int64_t numPoints, numBonds;
  std::int64_t step;
  double time, origin, dt;
  std::int64_t pointRecordBytes, bondRecordBytes;
  std::int64_t pointSection, bondSection, trailerOffset;
  std::uint32_t numNodeFields, numBondFields;
  // "name components\n" per node field, then "name d\n" / "name f\n" per bond field.
  char fields[kHeaderBytes - 128];
};
static_assert(sizeof(Header) == kHeaderBytes, "the header is 4096 bytes");

struct Trailer {
  char magic[8];
  std::uint64_t fileBytes, dataChecksum, headerChecksum;
};
static_assert(sizeof(Trailer) == 32, "the trailer is 32 bytes");

// Bond fields the set-up recomputes from the mesh: not history, not saved.
const char* const kDerivedBondFields[] = {"Reference_Bond_Length", "Influence_Function"};

std::uint64_t fnv(const void* data, std::size_t n, std::uint64_t h = 14695981039346656037ULL) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < n; ++k) {
    h ^= p[k];
    h *= 1099511628211ULL;
  }
  return h;
}

// Combined per point by a sum (mod 2^64): the total does not depend on how points are split.
std::uint64_t sumOverRanks(std::uint64_t local, MPI_Comm comm) {
  std::uint64_t total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_UINT64_T, MPI_SUM, comm);
  return total;
}

std::string mpiError(int code) {
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  return std::string(text, static_cast<std::size_t>(length));
}

std::string writeAt(MPI_File f, MPI_Offset offset, const char* data, std::size_t n) {
  while (n > 0) {
    const std::size_t chunk = std::min(n, kChunk);
    MPI_Status status;
    const int rc = MPI_File_write_at(f, offset, data, static_cast<int>(chunk), MPI_BYTE, &status);
    if (rc != MPI_SUCCESS) return mpiError(rc);
    offset += static_cast<MPI_Offset>(chunk);
    data += chunk;
    n -= chunk;
  }
  return "";
}

std::string readAt(MPI_File f, MPI_Offset offset, char* data, std::size_t n) {
  while (n > 0) {
    const std::size_t chunk = std::min(n, kChunk);
    MPI_Status status;
    const int rc = MPI_File_read_at(f, offset, data, static_cast<int>(chunk), MPI_BYTE, &status);
    if (rc != MPI_SUCCESS) return mpiError(rc);
    int got = 0;
    MPI_Get_count(&status, MPI_BYTE, &got);
    if (static_cast<std::size_t>(got) != chunk) return "unexpected end of file";
    offset += static_cast<MPI_Offset>(chunk);
    data += chunk;
    n -= chunk;
  }
  return "";
}

struct FieldList {
  std::vector<std::pair<std::string, int>> node;  // name, components
  std::vector<std::string> bondDouble, bondFloat;
  int nodeDoubles() const {
    int n = 0;
    for (const auto& f : node) n += f.second;
    return n;
  }
  std::int64_t pointRecordBytes() const {
    return 24 + 8 * static_cast<std::int64_t>(nodeDoubles());
  }
  std::int64_t bondRecordBytes() const {
    return 8 * static_cast<std::int64_t>(bondDouble.size()) +
           4 * static_cast<std::int64_t>(bondFloat.size());
  }
};

std::string describeFields(const FieldList& l) {
  std::string s;
  for (const auto& f : l.node) s += f.first + " " + std::to_string(f.second) + "\n";
  for (const auto& f : l.bondDouble) s += f + " d\n";
  for (const auto& f : l.bondFloat) s += f + " f\n";
  return s;
}

FieldList parseFields(const Header& h) {
  FieldList l;
  std::istringstream in(std::string(h.fields, strnlen(h.fields, sizeof h.fields)));
  std::string name, kind;
  for (std::uint32_t k = 0; k < h.numNodeFields && in >> name >> kind; ++k)
    l.node.emplace_back(name, std::atoi(kind.c_str()));
  for (std::uint32_t k = 0; k < h.numBondFields && in >> name >> kind; ++k)
    (kind == "f" ? l.bondFloat : l.bondDouble).push_back(name);
  return l;
}

}  // namespace

Checkpoint::Checkpoint(const RestartConfig& config, const Topology& topology, FieldManager& fields)
    : config_(config), topology_(topology), fields_(fields) {
  path_ = (std::filesystem::path(config_.directory) / config_.name).string();
  std::uint64_t local = 0;
  for (int i = 0; i < topology_.numOwned; ++i) {
    const long long gid = topology_.overlapGlobalId[i];
    std::uint64_t h = fnv(&gid, sizeof gid);
    h = fnv(&topology_.referencePosition[3 * i], 3 * sizeof(double), h);
    h = fnv(&topology_.volume[i], sizeof(double), h);
    h = fnv(&topology_.blockId[i], sizeof(int), h);
    for (auto b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b) {
      const long long j = topology_.overlapGlobalId[topology_.neighbors[b]];
      h = fnv(&j, sizeof j, h);
    }
    local += h;
  }
  meshHash_ = sumOverRanks(local, topology_.comm);
}

bool Checkpoint::exists() const {
  int found = 0;
  if (topology_.rank == 0) found = std::filesystem::exists(path_) ? 1 : 0;
  MPI_Bcast(&found, 1, MPI_INT, 0, topology_.comm);
  return found != 0;
}

std::vector<std::string> Checkpoint::historyBondFields(bool floats) const {
  std::vector<std::string> names =
      floats ? fields_.floatBondFieldNames() : fields_.bondFieldNames();
  names.erase(std::remove_if(names.begin(), names.end(),
                             [](const std::string& n) {
                               return std::find(std::begin(kDerivedBondFields),
                                                std::end(kDerivedBondFields),
                                                n) != std::end(kDerivedBondFields);
                             }),
              names.end());
  return names;
}

void Checkpoint::write(const CheckpointClock& clock, const std::vector<std::string>& nodeFields) {
  const auto start = std::chrono::steady_clock::now();
  const MPI_Comm comm = topology_.comm;
  const int n = topology_.numOwned;
  FieldList list;
  for (const auto& name : nodeFields)
    list.node.emplace_back(name, fields_.nodeField(name).components);
  list.bondDouble = historyBondFields(false);
  list.bondFloat = historyBondFields(true);
  const std::int64_t pointBytes = list.pointRecordBytes(), bondBytes = list.bondRecordBytes();
  const std::int64_t myBonds = topology_.numBonds();

  // Where this rank's records go: an exclusive scan over the ranks' point and bond counts.
  std::int64_t counts[2] = {n, myBonds}, before[2] = {0, 0};
  MPI_Exscan(counts, before, 2, MPI_INT64_T, MPI_SUM, comm);
  if (topology_.rank == 0) before[0] = before[1] = 0;  // MPI_Exscan leaves rank 0 undefined

  std::vector<char> points(static_cast<std::size_t>(n * pointBytes));
  std::vector<char> bonds(static_cast<std::size_t>(myBonds * bondBytes));
  std::vector<const double*> nodeData;
  for (const auto& f : list.node) nodeData.push_back(fields_.nodeField(f.first).data);
  std::vector<const double*> bondDouble;
  for (const auto& f : list.bondDouble) bondDouble.push_back(fields_.bond(f).data());
  std::vector<const float*> bondFloat;
  for (const auto& f : list.bondFloat) bondFloat.push_back(fields_.bondFloat(f).data());
  std::uint64_t checksum = 0;
  for (int i = 0; i < n; ++i) {
    char* p = points.data() + i * pointBytes;
    const std::int64_t header[3] = {topology_.overlapGlobalId[i], topology_.numNeighbors(i),
                                    before[1] + topology_.bondOffsets[i]};
    std::memcpy(p, header, sizeof header);
    double* values = reinterpret_cast<double*>(p + 24);
    for (std::size_t f = 0; f < list.node.size(); ++f) {
      const int c = list.node[f].second;
      for (int d = 0; d < c; ++d) *values++ = nodeData[f][c * i + d];
    }
    char* b0 = bonds.data() + topology_.bondOffsets[i] * bondBytes;
    for (auto b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b) {
      char* q = bonds.data() + b * bondBytes;
      for (const double* f : bondDouble) {
        std::memcpy(q, &f[b], 8);
        q += 8;
      }
      for (const float* f : bondFloat) {
        std::memcpy(q, &f[b], 4);
        q += 4;
      }
    }
    checksum += fnv(b0, static_cast<std::size_t>(topology_.numNeighbors(i) * bondBytes),
                    fnv(p, static_cast<std::size_t>(pointBytes)));
  }
  checksum = sumOverRanks(checksum, comm);

  Header h;
  std::memset(&h, 0, sizeof h);
  std::memcpy(h.magic, kMagic, 8);
  h.version = kVersion;
  h.headerBytes = kHeaderBytes;
  h.deckHash = config_.deckHash;
  h.meshHash = meshHash_;
  h.numPoints = topology_.globalNumPoints;
  h.numBonds = topology_.globalNumBonds;
  h.step = clock.step;
  h.time = clock.time;
  h.origin = clock.origin;
  h.dt = clock.dt;
  h.pointRecordBytes = pointBytes;
  h.bondRecordBytes = bondBytes;
  h.pointSection = kHeaderBytes;
  h.bondSection = h.pointSection + h.numPoints * pointBytes;
  h.trailerOffset = h.bondSection + h.numBonds * bondBytes;
  h.numNodeFields = static_cast<std::uint32_t>(list.node.size());
  h.numBondFields = static_cast<std::uint32_t>(list.bondDouble.size() + list.bondFloat.size());
  const std::string names = describeFields(list);
  if (names.size() >= sizeof h.fields) throw std::logic_error("checkpoint field list too long");
  std::memcpy(h.fields, names.data(), names.size());
  Trailer t;
  std::memcpy(t.magic, kEndMagic, 8);
  t.fileBytes = static_cast<std::uint64_t>(h.trailerOffset + static_cast<std::int64_t>(sizeof t));
  t.dataChecksum = checksum;
  t.headerChecksum = fnv(&h, sizeof h);

  const std::string temporary = path_ + ".tmp";
  std::string error;
  if (topology_.rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(config_.directory, ec);
    std::filesystem::remove(temporary, ec);
  }
  MPI_Barrier(comm);
  MPI_File file;
  int rc = MPI_File_open(comm, temporary.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL,
                         &file);
  if (rc != MPI_SUCCESS) {
    throwIfAnyRank(
        topology_.rank == 0 ? "cannot create checkpoint " + temporary + ": " + mpiError(rc) : "",
        comm, true);
  }
  if (topology_.rank == 0) {
    error = writeAt(file, 0, reinterpret_cast<const char*>(&h), sizeof h);
    if (error.empty())
      error = writeAt(file, h.trailerOffset, reinterpret_cast<const char*>(&t), sizeof t);
  }
  if (error.empty())
    error = writeAt(file, h.pointSection + before[0] * pointBytes, points.data(), points.size());
  if (error.empty())
    error = writeAt(file, h.bondSection + before[1] * bondBytes, bonds.data(), bonds.size());
  // Data on disk before the rename makes it the checkpoint (a crash leaves the old one).
  rc = MPI_File_sync(file);
  if (error.empty() && rc != MPI_SUCCESS) error = mpiError(rc);
  MPI_File_close(&file);
  if (!error.empty()) error = "writing checkpoint " + temporary + " failed: " + error;
  throwIfAnyRank(error, comm, true);
  if (topology_.rank == 0) {
    // The checkpoint name always holds a complete checkpoint: the previous one is linked (not
    // moved) to .prev, then the new one replaces it in one rename.
    std::error_code ec;
    const std::string previous = path_ + ".prev";
    std::filesystem::remove(previous, ec);
    if (std::filesystem::exists(path_)) {
      std::filesystem::create_hard_link(path_, previous, ec);
      if (ec) std::filesystem::copy_file(path_, previous, ec);  // no hard links on this system
      ec.clear();  // without a .prev the new checkpoint is still written
    }
    std::filesystem::rename(temporary, path_, ec);
    if (ec) error = "cannot rename " + temporary + " to " + path_ + ": " + ec.message();
    // The renames themselves reach the disk with the directory.
    const int dir = ::open(config_.directory.c_str(), O_RDONLY);
    if (dir >= 0) {
      ::fsync(dir);
      ::close(dir);
    }
  }
  throwIfAnyRank(error, comm, true);
  lastSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  lastBytes_ = static_cast<double>(t.fileBytes);
  pointRecordBytes_ = pointBytes;
  bondRecordBytes_ = bondBytes;
  ++count_;
  bytes_ += lastBytes_;
  seconds_ += lastSeconds_;
}

CheckpointClock Checkpoint::read() {
  const MPI_Comm comm = topology_.comm;
  const int rank = topology_.rank, size = topology_.numRanks;
  const std::string where = "checkpoint " + path_;
  Header h;
  Trailer t;
  std::memset(&h, 0, sizeof h);
  std::memset(&t, 0, sizeof t);
  // Rank 0 checks the frame (magic, version, length, trailer) before anyone reads further.
  std::string error;
  if (rank == 0) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path_, ec);
    std::FILE* f = ec ? nullptr : std::fopen(path_.c_str(), "rb");
    if (!f) {
      error = "cannot open " + where;
    } else if (bytes < sizeof h + sizeof t || std::fread(&h, sizeof h, 1, f) != 1) {
      error = where + " is truncated (" + std::to_string(bytes) + " bytes, less than a header)";
    } else if (std::memcmp(h.magic, kMagic, 8) != 0) {
      error = where + " is not a Peridot checkpoint (bad magic)";
    } else if (h.version != kVersion || h.headerBytes != kHeaderBytes) {
      error = where + " has format version " + std::to_string(h.version) + ", this Peridot reads " +
              std::to_string(kVersion);
    } else if (static_cast<std::uint64_t>(h.trailerOffset) + sizeof t != bytes) {
      error = where + " is truncated or damaged: " + std::to_string(bytes) +
              " bytes, its header says " + std::to_string(h.trailerOffset + sizeof t);
    } else if (std::fseek(f, static_cast<long>(h.trailerOffset), SEEK_SET) != 0 ||
               std::fread(&t, sizeof t, 1, f) != 1 || std::memcmp(t.magic, kEndMagic, 8) != 0 ||
               t.fileBytes != bytes) {
      error = where + " is incomplete (no valid trailer): it was not finished being written";
    } else if (t.headerChecksum != fnv(&h, sizeof h)) {
      error = where + " is damaged (header checksum mismatch)";
    }
    if (f) std::fclose(f);
  }
  if (!error.empty()) error += "; remove it (or use " + config_.name + ".prev) to go on";
  throwIfAnyRank(error, comm);
  MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, comm);
  MPI_Bcast(&t, sizeof t, MPI_BYTE, 0, comm);

  // Same problem? The deck hash covers models, discretization, conditions and solver settings.
  if (h.deckHash != config_.deckHash) {
    throw InputError(where +
                     " was written by a different deck (materials, damage, "
                     "discretization, blocks, conditions, contact or time step differ; "
                     "only Initial Time, Final Time, outputs and Restart may change)");
  }
  if (h.numPoints != topology_.globalNumPoints || h.numBonds != topology_.globalNumBonds ||
      h.meshHash != meshHash_) {
    throw InputError(
        where + " was written for another mesh: " + std::to_string(h.numPoints) + " points and " +
        std::to_string(h.numBonds) + " bonds, this run has " +
        std::to_string(topology_.globalNumPoints) + " and " +
        std::to_string(topology_.globalNumBonds) +
        (h.numPoints == topology_.globalNumPoints && h.numBonds == topology_.globalNumBonds
             ? " (reference positions, volumes or bond lists differ)"
             : ""));
  }
  const FieldList list = parseFields(h);
  if (list.pointRecordBytes() != h.pointRecordBytes || list.bondRecordBytes() != h.bondRecordBytes)
    throw InputError(where + " is damaged (field list does not match the record sizes)");

  // Each rank reads a contiguous run of point records, then the bonds of those points.
  const std::int64_t N = h.numPoints;
  const std::int64_t first = N * rank / size, last = N * (rank + 1) / size;
  const std::int64_t pointBytes = h.pointRecordBytes, bondBytes = h.bondRecordBytes;
  std::vector<char> points(static_cast<std::size_t>((last - first) * pointBytes));
  std::vector<char> bonds;
  MPI_File file;
  int rc = MPI_File_open(comm, path_.c_str(), MPI_MODE_RDONLY, MPI_INFO_NULL, &file);
  if (rc != MPI_SUCCESS) error = "cannot open " + where + ": " + mpiError(rc);
  throwIfAnyRank(error, comm);
  error = readAt(file, h.pointSection + first * pointBytes, points.data(), points.size());
  std::int64_t bondBegin = 0, bondEnd = 0;
  auto field = [&](std::int64_t k, int which) {
    std::int64_t v;
    std::memcpy(&v, points.data() + k * pointBytes + 8 * which, 8);
    return v;
  };
  if (error.empty() && last > first) {
    bondBegin = field(0, 2);
    bondEnd = bondBegin;
    for (std::int64_t k = 0; k < last - first && error.empty(); ++k) {
      if (field(k, 2) != bondEnd || field(k, 1) < 0) error = "bond offsets are inconsistent";
      bondEnd += field(k, 1);
    }
    if (error.empty() && (bondBegin < 0 || bondEnd > h.numBonds))
      error = "bond range out of bounds";
  }
  if (error.empty()) {
    bonds.resize(static_cast<std::size_t>((bondEnd - bondBegin) * bondBytes));
    error = readAt(file, h.bondSection + bondBegin * bondBytes, bonds.data(), bonds.size());
  }
  MPI_File_close(&file);
  if (!error.empty()) error = where + " is damaged: " + error;
  throwIfAnyRank(error, comm);

  // Each record goes to the owner of its point (Tpetra's directory answers who owns a gid).
  const std::size_t count = static_cast<std::size_t>(last - first);
  std::vector<GlobalOrdinal> gids(count);
  std::vector<int> owner(count);
  for (std::size_t k = 0; k < count; ++k) gids[k] = field(static_cast<std::int64_t>(k), 0);
  const auto status = topology_.ownedMap->getRemoteIndexList(
      Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), count),
      Teuchos::ArrayView<int>(owner.data(), count));
  if (status != Tpetra::AllIDsPresent) error = where + " holds point ids this mesh does not have";
  throwIfAnyRank(error, comm);
  std::vector<long long> sendBytes(size, 0);
  for (std::size_t k = 0; k < count; ++k)
    sendBytes[owner[k]] += pointBytes + field(static_cast<std::int64_t>(k), 1) * bondBytes;
  std::vector<long long> recvBytes(size, 0);
  MPI_Alltoall(sendBytes.data(), 1, MPI_LONG_LONG, recvBytes.data(), 1, MPI_LONG_LONG, comm);
  std::vector<int> sendCounts(size), sendDispls(size, 0), recvCounts(size), recvDispls(size, 0);
  long long sendTotal = 0, recvTotal = 0;
  for (int r = 0; r < size; ++r) {
    sendTotal += sendBytes[r];
    recvTotal += recvBytes[r];
  }
  if (sendTotal > INT_MAX || recvTotal > INT_MAX) {
    error = where + ": more than 2 GB per rank to redistribute; restart on more ranks";
  }
  throwIfAnyRank(error, comm, true);
  for (int r = 0; r < size; ++r) {
    sendCounts[r] = static_cast<int>(sendBytes[r]);
    recvCounts[r] = static_cast<int>(recvBytes[r]);
    if (r > 0) {
      sendDispls[r] = sendDispls[r - 1] + sendCounts[r - 1];
      recvDispls[r] = recvDispls[r - 1] + recvCounts[r - 1];
    }
  }
  std::vector<char> send(static_cast<std::size_t>(sendTotal));
  {
    std::vector<int> cursor(sendDispls);
    for (std::size_t k = 0; k < count; ++k) {
      const auto kk = static_cast<std::int64_t>(k);
      char* out = send.data() + cursor[owner[k]];
      std::memcpy(out, points.data() + kk * pointBytes, static_cast<std::size_t>(pointBytes));
      const std::int64_t nb = field(kk, 1);
      std::memcpy(out + pointBytes, bonds.data() + (field(kk, 2) - bondBegin) * bondBytes,
                  static_cast<std::size_t>(nb * bondBytes));
      cursor[owner[k]] += static_cast<int>(pointBytes + nb * bondBytes);
    }
  }
  points = std::vector<char>();
  bonds = std::vector<char>();
  std::vector<char> received(static_cast<std::size_t>(recvTotal));
  MPI_Alltoallv(send.data(), sendCounts.data(), sendDispls.data(), MPI_BYTE, received.data(),
                recvCounts.data(), recvDispls.data(), MPI_BYTE, comm);
  send = std::vector<char>();

  // Into the fields, checking that every owned point arrives once with its own bond count.
  std::vector<double*> nodeData;
  for (const auto& f : list.node) nodeData.push_back(fields_.node(f.first, f.second));
  std::vector<double*> bondDouble;
  for (const auto& f : list.bondDouble) bondDouble.push_back(fields_.bond(f).data());
  std::vector<float*> bondFloat;
  for (const auto& f : list.bondFloat) bondFloat.push_back(fields_.bondFloat(f).data());
  std::vector<char> seen(static_cast<std::size_t>(topology_.numOwned), 0);
  std::uint64_t checksum = 0;
  std::size_t pos = 0;
  while (pos < received.size() && error.empty()) {
    const char* p = received.data() + pos;
    std::int64_t head[3];
    std::memcpy(head, p, sizeof head);
    const int i = topology_.ownedMap->getLocalElement(head[0]);
    if (i < 0 || i >= topology_.numOwned || seen[i] || head[1] != topology_.numNeighbors(i)) {
      error =
          where + " does not match this mesh's bond list at point " + std::to_string(head[0] + 1);
      break;
    }
    seen[i] = 1;
    const double* values = reinterpret_cast<const double*>(p + 24);
    for (std::size_t f = 0; f < list.node.size(); ++f) {
      const int c = list.node[f].second;
      for (int d = 0; d < c; ++d) std::memcpy(&nodeData[f][c * i + d], values++, 8);
    }
    const char* q = p + pointBytes;
    for (auto b = topology_.bondOffsets[i]; b < topology_.bondOffsets[i + 1]; ++b) {
      for (double* f : bondDouble) {
        std::memcpy(&f[b], q, 8);
        q += 8;
      }
      for (float* f : bondFloat) {
        std::memcpy(&f[b], q, 4);
        q += 4;
      }
    }
    const std::size_t bytes = static_cast<std::size_t>(pointBytes + head[1] * bondBytes);
    checksum += fnv(p + pointBytes, bytes - static_cast<std::size_t>(pointBytes),
                    fnv(p, static_cast<std::size_t>(pointBytes)));
    pos += bytes;
  }
  if (error.empty() && std::count(seen.begin(), seen.end(), 0) > 0)
    error = where + " lacks some points of this mesh";
  throwIfAnyRank(error, comm);
  if (sumOverRanks(checksum, comm) != t.dataChecksum)
    throw InputError(where + " is damaged (data checksum mismatch)");

  CheckpointClock clock;
  clock.step = h.step;
  clock.time = h.time;
  clock.origin = h.origin;
  clock.dt = h.dt;
  return clock;
}

}  // namespace peridot
