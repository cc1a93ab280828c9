#include "discretization/TextMeshReader.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "core/CollectiveError.hpp"
#include "core/Error.hpp"
#include "core/Format.hpp"
#include "core/InputFile.hpp"
#include "discretization/Slicing.hpp"

namespace peridot {

namespace {

// What is wrong with one data line ("" when it is fine), the point it holds otherwise.
std::string parseLine(const std::string& line, int dimension, double thickness, double* x,
                      int& block, double& volume) {
  std::istringstream s(line);
  double blockValue;
  std::string extra;
  if (!(s >> x[0] >> x[1] >> x[2] >> blockValue >> volume) || (s >> extra)) {
    return "expected five numbers \"x y z block_id volume\"";
  }
  block = static_cast<int>(blockValue);
  if (block != blockValue || block < 1) return "the block id must be a positive integer";
  if (!(volume > 0) || !std::isfinite(x[0] + x[1] + x[2] + volume)) {
    return std::string("the ") + (dimension == 2 ? "area" : "volume") +
           " must be positive and all values finite";
  }
  if (dimension == 2) {
    if (x[2] != 0.0) {
      return "z is " + formatNumber(x[2]) + "; in a 2D discretization every point has z = 0";
    }
    volume *= thickness;  // the fifth column is the point's area
  }
  return "";
}

}  // namespace

PointCloud readTextMeshShare(const std::string& fileName, const std::string& deckPath,
                             int dimension, double thickness, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  {
    // Checked before opening: opening a FIFO would block.
    const std::string why = whyNotReadableFile(fileName);
    std::string problem;
    if (!why.empty()) {
      problem = InputError(deckPath, "cannot open text mesh \"" + fileName + "\": " + why).what();
    }
    throwIfAnyRank(problem, comm);
  }
  std::ifstream in(fileName, std::ios::binary);
  throwIfAnyRank(in ? std::string()
                    : InputError(deckPath, "cannot open text mesh \"" + fileName + "\"").what(),
                 comm);
  // This rank takes the lines that start in its byte range [begin, end).
  in.seekg(0, std::ios::end);
  const Slicing bytes{static_cast<long long>(in.tellg()), size};
  const long long begin = bytes.begin(rank), end = bytes.begin(rank + 1);
  long long at = begin;
  if (begin > 0 && begin < end) {
    // A line starts at begin only when the byte before it ends a line; else skip to the next.
    in.seekg(begin - 1);
    std::string rest;
    std::getline(in, rest);
    at = begin - 1 + static_cast<long long>(rest.size()) + 1;
  } else {
    in.seekg(begin);
  }

  PointCloud cloud;
  std::string line, problem;
  long long lines = 0;  // lines of this rank (up to the first bad one)
  while (at < end && std::getline(in, line)) {
    at += static_cast<long long>(line.size()) + 1;
    ++lines;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const char c0 = line[first];
    if (c0 == '#' || c0 == '/' || c0 == '*') continue;
    double x[3], volume = 0;
    int block = 0;
    problem = parseLine(line, dimension, thickness, x, block, volume);
    if (!problem.empty()) break;
    cloud.x.insert(cloud.x.end(), x, x + 3);
    cloud.blockId.push_back(block);
    cloud.volume.push_back(volume);
  }
  // Line numbers and point ids continue those of the ranks before (whose ranges come first).
  long long counts[2] = {lines, static_cast<long long>(cloud.size())}, before[2] = {0, 0};
  MPI_Exscan(counts, before, 2, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) before[0] = before[1] = 0;  // MPI_Exscan leaves rank 0's result undefined
  if (!problem.empty()) {
    problem = InputError(deckPath, "text mesh \"" + fileName + "\" line " +
                                       std::to_string(before[0] + lines) + ": " + problem)
                  .what();
  }
  throwIfAnyRank(problem, comm);
  cloud.globalId.resize(cloud.size());
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    cloud.globalId[p] = before[1] + static_cast<long long>(p);
  }
  MPI_Allreduce(&counts[1], &cloud.globalNumPoints, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (cloud.globalNumPoints == 0) {
    throw InputError(deckPath, "text mesh \"" + fileName + "\" contains no points");
  }
  // Every rank names every block: the union of the block ids (a handful) over the ranks.
  const std::set<int> mine(cloud.blockId.begin(), cloud.blockId.end());
  std::vector<int> local(mine.begin(), mine.end()), numbers(static_cast<std::size_t>(size));
  const int count = static_cast<int>(local.size());
  MPI_Allgather(&count, 1, MPI_INT, numbers.data(), 1, MPI_INT, comm);
  std::vector<int> displ(static_cast<std::size_t>(size), 0);
  for (int r = 1; r < size; ++r) displ[r] = displ[r - 1] + numbers[r - 1];
  std::vector<int> all(static_cast<std::size_t>(displ[size - 1] + numbers[size - 1]));
  MPI_Allgatherv(local.data(), count, MPI_INT, all.data(), numbers.data(), displ.data(), MPI_INT,
                 comm);
  for (int block : all) cloud.blockNames.emplace(block, "block_" + std::to_string(block));
  cloud.dimension = dimension;
  if (dimension == 2) cloud.thickness = thickness;
  return cloud;
}

}  // namespace peridot
