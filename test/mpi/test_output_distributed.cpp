// Output written one rank's range at a time (OutputDistribution + partial Exodus writes), on 1,
// 2 and 3 ranks: the file is the same, to the byte, as the one a single rank writes for the
// same points, and its content is what Peridigm's layout says (blocks by id, ids ascending in a
// block, node sets as output positions). Records are on disk as soon as written. Resuming keeps
// the earlier records and appends, a file that does not match is created anew, and a file that
// cannot be created says why.
#include <exodusII.h>
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "core/Error.hpp"
#include "output/ExodusCompare.hpp"
#include "output/OutputManager.hpp"
#include "parallel/Topology.hpp"

namespace peridot {
namespace {

constexpr long long kNumPoints = 103;  // not a multiple of 2 or 3: uneven ranges
const int kBlockOf[3] = {10, 3, 7};    // interleaved: block of id g is kBlockOf[g*g % 3]

int blockOf(long long g) { return kBlockOf[(g * g) % 3]; }
double coordinate(long long g, int d) { return 0.25 * static_cast<double>(g) - 3.0 * d + 0.1; }
bool inSet(const std::string& set, long long g) {
  if (set == "even") return g % 2 == 0;
  if (set == "sparse") return g % 17 == 3;
  return false;  // "empty"
}
const char* kSets[3] = {"even", "sparse", "empty"};

// Owner of id g among P ranks: scattered, and not in id order within a rank.
int ownerOf(long long g, int P) { return static_cast<int>((g * 7 + g / 5) % P); }

// The points of `rank` among `P`, in a scrambled (not id-sorted) order.
Topology topologyOf(MPI_Comm comm) {
  Topology t;
  t.comm = comm;
  MPI_Comm_rank(comm, &t.rank);
  MPI_Comm_size(comm, &t.numRanks);
  t.globalNumPoints = kNumPoints;
  std::vector<long long> ids;
  for (long long g = 0; g < kNumPoints; ++g)
    if (ownerOf(g, t.numRanks) == t.rank) ids.push_back(g);
  std::stable_sort(ids.begin(), ids.end(),
                   [](long long a, long long b) { return (a * 37) % 11 < (b * 37) % 11; });
  t.numOwned = t.numOverlap = static_cast<int>(ids.size());
  for (long long g : ids) {
    t.overlapGlobalId.push_back(g);
    t.blockId.push_back(blockOf(g));
    for (int d = 0; d < 3; ++d) t.referencePosition.push_back(coordinate(g, d));
  }
  return t;
}

// Values that depend on the point and on a per-run offset (to tell two runs' records apart).
class TestSource : public VariableSource {
 public:
  TestSource(const Topology& t, double offset) : t_(t), offset_(offset) {}
  double time = 0.0;
  void nodeVariable(const std::string& name, std::vector<double>& v) override {
    v.clear();
    for (int i = 0; i < t_.numOwned; ++i) {
      const long long g = t_.overlapGlobalId[i];
      if (name == "Damage") {
        v.push_back(std::sin(static_cast<double>(g)) + time + offset_);
      } else {
        for (int d = 0; d < 3; ++d) v.push_back(expectedVector(g, d, time, offset_));
      }
    }
  }
  void globalVariable(const std::string&, std::vector<double>& v) override {
    v = {time * 2.0 + offset_};
  }
  int components(const std::string& name) const override {
    return name == "Damage" ? 1 : name == "Energy" ? 0 : 3;
  }
  int globalSize(const std::string&) const override { return 1; }
  static double expectedVector(long long g, int d, double time, double offset) {
    return 1e-3 * static_cast<double>(g) + d + time + offset;
  }

 private:
  const Topology& t_;
  double offset_;
};

RunConfig configFor(const std::string& stem, const std::vector<std::string>& variables) {
  RunConfig c;
  OutputConfig out;
  out.name = "Output";
  out.fileName = stem;
  out.frequency = 1;
  out.variables = variables;
  c.outputs.push_back(out);
  return c;
}

std::map<std::string, std::vector<long long>> setsOf(const Topology& t) {
  std::map<std::string, std::vector<long long>> sets;
  for (const char* name : kSets) {
    auto& members = sets[name];
    for (int i = 0; i < t.numOwned; ++i)
      if (inSet(name, t.overlapGlobalId[i])) members.push_back(t.overlapGlobalId[i]);
    std::sort(members.begin(), members.end());
  }
  return sets;
}

const std::map<int, std::string> kBlockNames = {{3, "three"}, {7, "seven"}, {10, "ten"}};
const std::vector<std::string> kVariables = {"Displacement", "Damage", "Energy"};

// Writes records at `times` (steps 0, 1, ...), after resuming at `resumeTime` when given.
std::vector<std::string> run(MPI_Comm comm, const std::string& stem, int dimension,
                             const std::vector<double>& times, double offset,
                             const std::vector<std::string>& variables = kVariables,
                             const double* resumeTime = nullptr, long long firstStep = 0) {
  Topology t = topologyOf(comm);
  TestSource source(t, offset);
  Timers timers;
  OutputManager out(configFor(stem, variables), kBlockNames, dimension, setsOf(t), t, source,
                    timers);
  std::vector<std::string> messages;
  if (resumeTime != nullptr) messages = out.resume(firstStep - 1, *resumeTime);
  for (std::size_t k = 0; k < times.size(); ++k) {
    source.time = times[k];
    out.write(firstStep + static_cast<long long>(k), times[k]);
  }
  return messages;
}

// A path every rank agrees on (rank 0's process id in it).
std::string sharedStem(const std::string& what) {
  long long pid = ::getpid();
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  return (std::filesystem::temp_directory_path() /
          ("peridot_output_distributed_" + std::to_string(pid) + "_" + what))
      .string();
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// The ids in output order: blocks by id, ids ascending within a block.
std::vector<long long> expectedOrder() {
  std::vector<long long> order;
  for (int block : {3, 7, 10})
    for (long long g = 0; g < kNumPoints; ++g)
      if (blockOf(g) == block) order.push_back(g);
  return order;
}

// Checks a file's content against the formulas (rank 0).
void expectContent(const std::string& path, int dimension, const std::vector<double>& times,
                   const std::vector<double>& offsets) {
  const ExodusResults r = readExodusResults(path);
  const std::vector<long long> order = expectedOrder();
  ASSERT_EQ(r.dimension, dimension);
  ASSERT_EQ(r.nodeIds.size(), order.size());
  ASSERT_EQ(r.times, times);
  const std::vector<std::string> nodal =
      dimension == 2 ? std::vector<std::string>{"DisplacementX", "DisplacementY"}
                     : std::vector<std::string>{"DisplacementX", "DisplacementY", "DisplacementZ"};
  EXPECT_EQ(r.nodalNames, nodal);
  EXPECT_EQ(r.elementNames, std::vector<std::string>{"Damage"});
  EXPECT_EQ(r.globalNames, std::vector<std::string>{"Energy"});
  for (std::size_t p = 0; p < order.size(); ++p) {
    const long long g = order[p];
    EXPECT_EQ(r.nodeIds[p], g + 1);
    EXPECT_EQ(r.elementIds[p], g + 1);
    EXPECT_EQ(r.elementBlock[p], blockOf(g));
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(r.nodeCoordinates[3 * p + d], d < dimension ? coordinate(g, d) : 0.0);
    }
    for (std::size_t s = 0; s < times.size(); ++s) {
      for (int d = 0; d < dimension; ++d) {
        EXPECT_EQ(r.nodal[d][s][p], TestSource::expectedVector(g, d, times[s], offsets[s]))
            << "point " << g << " record " << s;
      }
      EXPECT_EQ(r.element[0][s][p], std::sin(static_cast<double>(g)) + times[s] + offsets[s]);
    }
  }
  for (std::size_t s = 0; s < times.size(); ++s)
    EXPECT_EQ(r.global[0][s][0], times[s] * 2.0 + offsets[s]);

  // Node sets: 1-based output positions of the members, ascending.
  int cpu = sizeof(double), io = 0;
  float version = 0;
  const int exoid = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(exoid, 0);
  for (int s = 0; s < 3; ++s) {
    // Sets are in name order: empty, even, sparse.
    const std::string names[3] = {"empty", "even", "sparse"};
    std::vector<int> expected;
    for (std::size_t p = 0; p < order.size(); ++p)
      if (inSet(names[s], order[p])) expected.push_back(static_cast<int>(p + 1));
    int count = 0, df = 0;
    ASSERT_GE(ex_get_set_param(exoid, EX_NODE_SET, s + 1, &count, &df), 0);
    ASSERT_EQ(count, static_cast<int>(expected.size())) << names[s];
    std::vector<int> nodes(expected.size() + 1, 0);
    if (count > 0) {
      EXPECT_GE(ex_get_set(exoid, EX_NODE_SET, s + 1, nodes.data(), nullptr), 0);
    }
    nodes.resize(expected.size());
    EXPECT_EQ(nodes, expected) << names[s];
    char name[64] = {0};
    EXPECT_GE(ex_get_name(exoid, EX_NODE_SET, s + 1, name), 0);
    EXPECT_EQ(std::string(name), names[s]);
  }
  ex_close(exoid);
}

class OutputDistributed : public ::testing::TestWithParam<int> {};

TEST_P(OutputDistributed, FileIsTheSameAsOneRanksAndFollowsTheLayout) {
  const int dimension = GetParam();
  const std::string all = sharedStem("all" + std::to_string(dimension));
  const std::string one = sharedStem("one" + std::to_string(dimension));
  const std::vector<double> times = {0.0, 0.125, 0.25};
  run(MPI_COMM_WORLD, all, dimension, times, 0.0);
  if (rank() == 0) {
    run(MPI_COMM_SELF, one, dimension, times, 0.0);
    expectContent(all + ".e", dimension, times, {0, 0, 0});
    const std::string a = bytesOf(all + ".e"), b = bytesOf(one + ".e");
    EXPECT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "the file written on all ranks differs from one rank's";
    std::filesystem::remove(all + ".e");
    std::filesystem::remove(one + ".e");
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

TEST_P(OutputDistributed, ResumeKeepsEarlierRecordsAndAppends) {
  const int dimension = GetParam();
  const std::string stem = sharedStem("resume" + std::to_string(dimension));
  // A first run writes four records; the restart is at the second (time 0.1), and the continued
  // run (offset 100, to tell its values apart) writes steps 2 and 3 again.
  run(MPI_COMM_WORLD, stem, dimension, {0.0, 0.1, 0.2, 0.3}, 0.0);
  const double restart = 0.1;
  const auto messages =
      run(MPI_COMM_WORLD, stem, dimension, {0.2, 0.3}, 100.0, kVariables, &restart, 2);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("continuing"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("record 2"), std::string::npos) << messages[0];
  if (rank() == 0) {
    expectContent(stem + ".e", dimension, {0.0, 0.1, 0.2, 0.3}, {0, 0, 100, 100});
    std::filesystem::remove(stem + ".e");
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

TEST_P(OutputDistributed, ResumeRecreatesAFileThatDoesNotMatchOrIsMissing) {
  const int dimension = GetParam();
  const std::string stem = sharedStem("mismatch" + std::to_string(dimension));
  // Other variables than the continued run's: not continued.
  run(MPI_COMM_WORLD, stem, dimension, {0.0, 0.1, 0.2}, 0.0, {"Damage", "Energy"});
  const double restart = 0.1;
  auto messages = run(MPI_COMM_WORLD, stem, dimension, {0.2}, 100.0, kVariables, &restart, 2);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("created anew"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("variables differ"), std::string::npos) << messages[0];
  if (rank() == 0) expectContent(stem + ".e", dimension, {0.2}, {100});
  // The other dimension: not continued either.
  messages = run(MPI_COMM_WORLD, stem, 5 - dimension, {0.2}, 100.0, kVariables, &restart, 2);
  EXPECT_NE(messages.at(0).find("dimension"), std::string::npos) << messages[0];
  if (rank() == 0) std::filesystem::remove(stem + ".e");
  MPI_Barrier(MPI_COMM_WORLD);
  // Missing.
  messages = run(MPI_COMM_WORLD, stem, dimension, {0.2}, 100.0, kVariables, &restart, 2);
  EXPECT_NE(messages.at(0).find("created anew"), std::string::npos) << messages[0];
  if (rank() == 0) {
    expectContent(stem + ".e", dimension, {0.2}, {100});
    std::filesystem::remove(stem + ".e");
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

TEST_P(OutputDistributed, EachRecordIsOnDiskBeforeTheFileIsClosed) {
  // A run killed between records must leave a readable file holding every record written.
  const int dimension = GetParam();
  const std::string stem = sharedStem("flush" + std::to_string(dimension));
  Topology t = topologyOf(MPI_COMM_WORLD);
  TestSource source(t, 0.0);
  Timers timers;
  OutputManager out(configFor(stem, kVariables), kBlockNames, dimension, setsOf(t), t, source,
                    timers);
  for (int s = 0; s < 2; ++s) {
    source.time = 0.5 * s;
    out.write(s, source.time);
  }
  if (rank() == 0) expectContent(stem + ".e", dimension, {0.0, 0.5}, {0, 0});
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() == 0) std::filesystem::remove(stem + ".e");
}

INSTANTIATE_TEST_SUITE_P(Dimensions, OutputDistributed, ::testing::Values(3, 2));

TEST(OutputDistributedErrors, AFileThatCannotBeCreatedIsNamedWithTheReason) {
  const std::string stem =
      sharedStem("no_such_directory") + "/nested/out";  // the directory does not exist
  try {
    run(MPI_COMM_WORLD, stem, 3, {0.0}, 0.0);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    // Checked before any file is created (the output path is a deck error now), on every rank,
    // with the file and the OS reason.
    const std::string what = e.what();
    EXPECT_NE(what.find(stem + ".e"), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace peridot
