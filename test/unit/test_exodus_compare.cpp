// The .comp parser, the Exodus result reader and the result/gold comparison behind peridot-diff.
#include <exodusII.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "TempFile.hpp"
#include "core/Error.hpp"
#include "output/ExodusCompare.hpp"

#ifndef PERIDOT_SHARED_DIR
#define PERIDOT_SHARED_DIR "../shared"
#endif

namespace {

using peridot::CompSpec;
using peridot::InputError;
using peridot::Tolerance;

const std::string kCases = std::string(PERIDOT_SHARED_DIR) + "/peridigm-cases";

struct Case {
  std::string comp;
  std::string gold;
};

const std::vector<Case>& shippedCases() {
  static const std::vector<Case> cases = {
      {"BondBreakingInitialVelocity/BondBreakingInitialVelocity.comp",
       "BondBreakingInitialVelocity/BondBreakingInitialVelocity_gold.e"},
      {"Compression_2x1x1/Compression_2x1x1.comp", "Compression_2x1x1/Compression_2x1x1_gold.e"},
      {"Contact_Cubes/Contact_Cubes.comp", "Contact_Cubes/Contact_Cubes_gold.e"},
      {"ElasticBondBased3D/ElasticBondBased.comp", "ElasticBondBased3D/ElasticBondBased3D_gold.e"},
      {"WaveInBar/WaveInBar.comp", "WaveInBar/WaveInBar_gold.e"},
  };
  return cases;
}

using peridot::testing::TempFile;
using peridot::testing::tempPath;

template <class F>
void expectInputError(F f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no InputError thrown";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const auto& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "message \"" << message << "\" lacks \"" << part << "\"";
    }
  }
}

const peridot::VariableReport* findReport(const peridot::CompareReport& report,
                                          const std::string& kind, const std::string& name) {
  for (const auto& v : report.variables) {
    if (v.kind == kind && v.name == name) return &v;
  }
  return nullptr;
}

std::string printed(const peridot::CompareReport& report, bool quiet = false) {
  std::ostringstream out;
  peridot::printCompareReport(out, report, quiet);
  return out.str();
}

// ---- Tolerance ----

TEST(Tolerance, AbsoluteRelativeAndFloor) {
  Tolerance abs{Tolerance::Kind::Absolute, 1e-3, 0.0};
  EXPECT_TRUE(abs.passes(1.0, 1.001));  // diff <= tol passes
  EXPECT_FALSE(abs.passes(1.0, 1.0011));
  EXPECT_DOUBLE_EQ(abs.allowed(5.0, 7.0), 1e-3);

  Tolerance rel{Tolerance::Kind::Relative, 1e-2, 0.0};
  EXPECT_TRUE(rel.passes(100.0, 101.0));
  EXPECT_FALSE(rel.passes(100.0, 102.0));
  EXPECT_DOUBLE_EQ(rel.allowed(-200.0, 100.0), 2.0);
  EXPECT_FALSE(rel.passes(0.0, 1e-300));

  Tolerance floored{Tolerance::Kind::Relative, 1e-2, 1e-8};
  EXPECT_TRUE(floored.passes(0.0, 5e-9));   // both below the floor: ignored
  EXPECT_FALSE(floored.passes(0.0, 2e-8));  // one above: compared

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(abs.passes(nan, nan));
  EXPECT_FALSE(abs.passes(nan, 0.0));
  EXPECT_FALSE(abs.passes(0.0, nan));
  EXPECT_TRUE(abs.passes(inf, inf));
  EXPECT_FALSE(abs.passes(inf, -inf));
  EXPECT_FALSE(rel.passes(inf, 1.0));
  EXPECT_EQ(floored.describe(), "relative 0.01 floor 1e-08");
}

// ---- .comp parsing ----

TEST(CompParser, ParsesAllSections) {
  const std::string text =
      "# a comment\n"
      "DEFAULT TOLERANCE absolute 1.0E-9\n"
      "COORDINATES absolute 1.0E-12\n"
      "TIME STEPS absolute 1.0E-14\n"
      "NODAL VARIABLES absolute 1.0E-12\n"
      "\tDisplacementX   absolute 5.0E-14\n"
      "  VelocityX relative 1.E-8 floor 1e-20   # trailing comment\n"
      "\tForceX\n"
      "ELEMENT VARIABLES\n"
      "\tDamage absolute 1.0E-3\n"
      "\tDilatation\n"
      "GLOBAL VARIABLES relative 1e-6\n";
  const CompSpec spec = peridot::parseCompText(text, "test.comp");
  EXPECT_EQ(spec.defaultTolerance.kind, Tolerance::Kind::Absolute);
  EXPECT_DOUBLE_EQ(spec.defaultTolerance.value, 1e-9);
  EXPECT_DOUBLE_EQ(spec.coordinateTolerance().value, 1e-12);
  EXPECT_DOUBLE_EQ(spec.timeTolerance().value, 1e-14);
  ASSERT_EQ(spec.nodal.variables.size(), 3u);
  EXPECT_EQ(spec.nodal.variables[0].first, "DisplacementX");
  EXPECT_DOUBLE_EQ(spec.nodal.variables[0].second.value, 5e-14);
  EXPECT_EQ(spec.nodal.variables[1].second.kind, Tolerance::Kind::Relative);
  EXPECT_DOUBLE_EQ(spec.nodal.variables[1].second.value, 1e-8);
  EXPECT_DOUBLE_EQ(spec.nodal.variables[1].second.floor, 1e-20);
  EXPECT_DOUBLE_EQ(spec.nodal.variables[2].second.value, 1e-12);  // the section default
  ASSERT_EQ(spec.element.variables.size(), 2u);
  EXPECT_DOUBLE_EQ(spec.element.variables[1].second.value, 1e-9);  // DEFAULT TOLERANCE
  EXPECT_TRUE(spec.global.present);
  EXPECT_TRUE(spec.global.variables.empty());
  EXPECT_EQ(spec.sectionDefault(spec.global).kind, Tolerance::Kind::Relative);
}

TEST(CompParser, DefaultsWithoutDefaultTolerance) {
  const CompSpec spec =
      peridot::parseCompText("NODAL VARIABLES\n\tA\nDEFAULT TOLERANCE absolute 2\n", "x.comp");
  ASSERT_EQ(spec.nodal.variables.size(), 1u);
  // DEFAULT TOLERANCE applies even when it comes later in the file.
  EXPECT_EQ(spec.nodal.variables[0].second.kind, Tolerance::Kind::Absolute);
  EXPECT_DOUBLE_EQ(spec.nodal.variables[0].second.value, 2.0);
  const CompSpec empty = peridot::parseCompText("", "empty.comp");
  EXPECT_EQ(empty.defaultTolerance.kind, Tolerance::Kind::Relative);  // exodiff's default
  EXPECT_DOUBLE_EQ(empty.coordinateTolerance().value, 1e-6);
  EXPECT_FALSE(empty.nodal.present);
}

TEST(CompParser, ErrorsNameTheLine) {
  expectInputError([] { peridot::parseCompText("DEFAULT TOLERANCE combined 1e-9\n", "a.comp"); },
                   {"a.comp, line 1", "combined"});
  expectInputError([] { peridot::parseCompText("COORDINATES absolute\n", "a.comp"); },
                   {"line 1", "missing the value"});
  expectInputError([] { peridot::parseCompText("\n\tDisplacementX absolute 1\n", "a.comp"); },
                   {"line 2", "outside"});
  expectInputError([] { peridot::parseCompText("SIDESET VARIABLES\n", "a.comp"); },
                   {"line 1", "SIDESET"});
  expectInputError([] { peridot::parseCompText("TIME STEPS absolute abc\n", "a.comp"); },
                   {"\"abc\""});
  expectInputError(
      [] { peridot::parseCompText("NODAL VARIABLES\n\tA absolute 1 floor\n", "a.comp"); },
      {"line 2", "floor"});
  expectInputError(
      [] { peridot::parseCompText("NODAL VARIABLES\n\tA absolute 1\n\ta\n", "a.comp"); },
      {"line 3", "twice"});
  expectInputError([] { peridot::parseCompFile("/nonexistent/x.comp"); }, {"/nonexistent/x.comp"});
}

TEST(CompParser, ParsesTheShippedFiles) {
  for (const auto& c : shippedCases()) {
    SCOPED_TRACE(c.comp);
    const CompSpec spec = peridot::parseCompFile(kCases + "/" + c.comp);
    EXPECT_DOUBLE_EQ(spec.defaultTolerance.value, 1e-9);
    EXPECT_DOUBLE_EQ(spec.coordinateTolerance().value, 1e-12);
    EXPECT_DOUBLE_EQ(spec.timeTolerance().value, 1e-14);
    EXPECT_FALSE(spec.nodal.variables.empty());
  }
  const CompSpec wave = peridot::parseCompFile(kCases + "/WaveInBar/WaveInBar.comp");
  ASSERT_EQ(wave.nodal.variables.size(), 9u);
  EXPECT_EQ(wave.nodal.variables[6].first, "Force_DensityX");
  EXPECT_DOUBLE_EQ(wave.nodal.variables[6].second.value, 5.0);
  ASSERT_EQ(wave.element.variables.size(), 2u);
  EXPECT_DOUBLE_EQ(wave.element.variables[0].second.value, 1e-15);
}

// ---- reading and comparing the shipped golds ----

TEST(ExodusCompare, EveryGoldMatchesItself) {
  for (const auto& c : shippedCases()) {
    SCOPED_TRACE(c.gold);
    const CompSpec spec = peridot::parseCompFile(kCases + "/" + c.comp);
    const auto gold = peridot::readExodusResults(kCases + "/" + c.gold);
    EXPECT_FALSE(gold.times.empty());
    EXPECT_EQ(gold.nodeIds.size(), gold.elementIds.size());
    const auto report = peridot::compareExodusResults(gold, gold, spec);
    EXPECT_TRUE(report.passed()) << printed(report);
    EXPECT_TRUE(report.problems.empty());
    EXPECT_EQ(report.failures(), 0u);
    EXPECT_GT(report.valuesCompared(), 0u);
    EXPECT_NE(printed(report).find("PASSED"), std::string::npos);
  }
}

TEST(ExodusCompare, ReadsContactCubesGlobalsAndBlocks) {
  const auto gold = peridot::readExodusResults(kCases + "/Contact_Cubes/Contact_Cubes_gold.e");
  EXPECT_EQ(gold.times.size(), 20u);
  EXPECT_EQ(gold.nodeIds.size(), 128u);
  ASSERT_EQ(gold.globalNames.size(), 3u);
  EXPECT_EQ(gold.globalNames[0], "Global_Kinetic_Energy");
  EXPECT_EQ(gold.global.size(), 3u);
  EXPECT_EQ(gold.global[0].size(), 20u);
  EXPECT_EQ(std::count(gold.elementBlock.begin(), gold.elementBlock.end(), 2), 64);
  ASSERT_EQ(gold.elementNames.size(), 5u);
  for (double v : gold.element[3][0]) EXPECT_FALSE(std::isnan(v));  // Weighted_Volume, step 1
}

// Copies a gold file and changes one value with the Exodus API.
void modifiedCopy(const std::string& gold, const std::string& copy,
                  const std::function<void(int exoid)>& change) {
  std::filesystem::copy_file(gold, copy, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::permissions(
      copy, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  int cpuWordSize = sizeof(double);
  int ioWordSize = 0;
  float version = 0.0f;
  const int exoid = ex_open(copy.c_str(), EX_WRITE, &cpuWordSize, &ioWordSize, &version);
  ASSERT_GE(exoid, 0);
  change(exoid);
  ASSERT_EQ(ex_close(exoid), 0);
}

TEST(ExodusCompare, FindsOneChangedNodalValue) {
  const std::string goldPath = kCases + "/WaveInBar/WaveInBar_gold.e";
  const auto gold = peridot::readExodusResults(goldPath);
  const auto var = std::find(gold.nodalNames.begin(), gold.nodalNames.end(), "DisplacementX");
  ASSERT_NE(var, gold.nodalNames.end());
  const int varIndex = static_cast<int>(var - gold.nodalNames.begin()) + 1;
  const int step = 5;
  const std::size_t node = 10;
  std::vector<double> values = gold.nodal[static_cast<std::size_t>(varIndex - 1)][step - 1];
  const double original = values[node];
  values[node] += 1e-6;  // far above the 5e-14 tolerance

  TempFile copy(tempPath("wave.e"));
  modifiedCopy(goldPath, copy.path, [&](int exoid) {
    ASSERT_EQ(ex_put_var(exoid, step, EX_NODAL, varIndex, 1, static_cast<int64_t>(values.size()),
                         values.data()),
              0);
  });
  const auto spec = peridot::parseCompFile(kCases + "/WaveInBar/WaveInBar.comp");
  const auto result = peridot::readExodusResults(copy.path);
  const auto report = peridot::compareExodusResults(result, gold, spec);
  EXPECT_FALSE(report.passed());
  EXPECT_TRUE(report.problems.empty());
  EXPECT_EQ(report.failures(), 1u);
  const auto* v = findReport(report, "nodal", "DisplacementX");
  ASSERT_NE(v, nullptr);
  ASSERT_EQ(v->failures, 1u);
  ASSERT_EQ(v->shown.size(), 1u);
  const auto& d = v->shown[0];
  EXPECT_EQ(d.step, step);
  EXPECT_DOUBLE_EQ(d.time, gold.times[step - 1]);
  EXPECT_EQ(d.id, gold.nodeIds[node]);
  EXPECT_EQ(d.result, original + 1e-6);
  EXPECT_EQ(d.gold, original);
  EXPECT_NEAR(d.difference, 1e-6, 1e-15);
  EXPECT_DOUBLE_EQ(d.allowed, 5e-14);
  const std::string text = printed(report);
  EXPECT_NE(text.find("nodal DisplacementX step 5"), std::string::npos) << text;
  EXPECT_NE(text.find("id " + std::to_string(gold.nodeIds[node])), std::string::npos);
  EXPECT_NE(text.find("FAILED: 1 values over tolerance in 1 variables"), std::string::npos);

  // The same values the other way round: the result as gold.
  const auto reverse = peridot::compareExodusResults(gold, result, spec);
  EXPECT_EQ(reverse.failures(), 1u);
}

TEST(ExodusCompare, FindsOneChangedElementValueInSecondBlock) {
  const std::string goldPath = kCases + "/Contact_Cubes/Contact_Cubes_gold.e";
  const auto gold = peridot::readExodusResults(goldPath);
  const auto var =
      std::find(gold.elementNames.begin(), gold.elementNames.end(), "Stored_Elastic_Energy");
  ASSERT_NE(var, gold.elementNames.end());
  const int varIndex = static_cast<int>(var - gold.elementNames.begin()) + 1;
  const int step = 3;
  // Element 5 of block 2 (file order: block 1's 64 elements first).
  const std::size_t firstOfBlock2 = static_cast<std::size_t>(
      std::find(gold.elementBlock.begin(), gold.elementBlock.end(), 2) - gold.elementBlock.begin());
  const std::size_t element = firstOfBlock2 + 5;
  const auto& all = gold.element[static_cast<std::size_t>(varIndex - 1)][step - 1];
  std::vector<double> block2(all.begin() + static_cast<std::ptrdiff_t>(firstOfBlock2),
                             all.begin() + static_cast<std::ptrdiff_t>(firstOfBlock2 + 64));
  block2[5] += 1.0;

  // And one global value.
  std::vector<double> globals(gold.globalNames.size());
  for (std::size_t g = 0; g < globals.size(); ++g) globals[g] = gold.global[g][step - 1][0];
  globals[2] *= 1.5;
  globals[2] += 1.0;

  TempFile copy(tempPath("cubes.e"));
  modifiedCopy(goldPath, copy.path, [&](int exoid) {
    ASSERT_EQ(ex_put_var(exoid, step, EX_ELEM_BLOCK, varIndex, 2, 64, block2.data()), 0);
    ASSERT_EQ(ex_put_glob_vars(exoid, step, static_cast<int>(globals.size()), globals.data()), 0);
  });
  const auto spec = peridot::parseCompFile(kCases + "/Contact_Cubes/Contact_Cubes.comp");
  const auto report =
      peridot::compareExodusResults(peridot::readExodusResults(copy.path), gold, spec);
  EXPECT_TRUE(report.problems.empty());
  // Contact_Cubes.comp has no GLOBAL VARIABLES section: globals are not compared (exodiff's rule).
  EXPECT_EQ(report.failures(), 1u) << printed(report);
  const auto* v = findReport(report, "element", "Stored_Elastic_Energy");
  ASSERT_NE(v, nullptr);
  ASSERT_EQ(v->shown.size(), 1u);
  EXPECT_EQ(v->shown[0].id, gold.elementIds[element]);
  EXPECT_EQ(v->shown[0].step, step);
  EXPECT_EQ(findReport(report, "global", gold.globalNames[2]), nullptr);
  // With a GLOBAL VARIABLES section (no names: all of them, section default) the change shows.
  const auto withGlobals = peridot::parseCompText(
      "DEFAULT TOLERANCE absolute 1.0E-9\nGLOBAL VARIABLES\n", "globals.comp");
  const auto report2 =
      peridot::compareExodusResults(peridot::readExodusResults(copy.path), gold, withGlobals);
  const auto* g = findReport(report2, "global", gold.globalNames[2]);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->failures, 1u);
  EXPECT_DOUBLE_EQ(g->tolerance.value, 1e-9);
}

TEST(ExodusCompare, CapsShownDifferencesButCountsAll) {
  const std::string goldPath = kCases + "/WaveInBar/WaveInBar_gold.e";
  const auto gold = peridot::readExodusResults(goldPath);
  auto result = gold;
  for (auto& value : result.nodal[0][3]) value += 1.0;  // 525 differences
  CompSpec spec = peridot::parseCompFile(kCases + "/WaveInBar/WaveInBar.comp");
  const auto report = peridot::compareExodusResults(result, gold, spec, {50});
  const auto* v = findReport(report, "nodal", gold.nodalNames[0]);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->failures, 525u);
  EXPECT_EQ(v->shown.size(), 50u);
  const std::string text = printed(report);
  EXPECT_NE(text.find("475 more differences"), std::string::npos) << text;
  const std::string quiet = printed(report, true);
  EXPECT_EQ(quiet.find(" id "), std::string::npos);
  EXPECT_NE(quiet.find("525 of"), std::string::npos);
}

// ---- small result files written by the test ----

struct TestResults {
  std::vector<std::pair<int64_t, std::vector<int64_t>>> blocks;  // block id, element ids in order
  std::vector<int64_t> nodeOrder;                                // node ids in file order
  std::vector<std::string> nodal = {"DisplacementX"};
  std::vector<std::string> element = {"Damage"};
  std::vector<std::string> global = {"Energy"};
  int steps = 3;
  // Values as functions of (id, step); coordinates of node id are (id, 2 id, 3 id).
  std::function<double(int64_t, int)> nodalValue = [](int64_t id, int s) { return id + 0.1 * s; };
  std::function<double(int64_t, int)> elementValue = [](int64_t id, int s) {
    return 1.0 / (id + s);
  };
};

void writeResults(const std::string& path, const TestResults& spec) {
  int cpuWordSize = sizeof(double);
  int ioWordSize = sizeof(double);
  const int exoid = ex_create(path.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  ASSERT_GE(exoid, 0);
  ex_set_int64_status(exoid, EX_ALL_INT64_API);
  std::vector<int64_t> elementIds;
  for (const auto& b : spec.blocks)
    elementIds.insert(elementIds.end(), b.second.begin(), b.second.end());
  const auto numNodes = static_cast<int64_t>(spec.nodeOrder.size());
  ASSERT_GE(ex_put_init(exoid, "results", 3, numNodes, static_cast<int64_t>(elementIds.size()),
                        static_cast<int64_t>(spec.blocks.size()), 0, 0),
            0);
  std::vector<double> x, y, z;
  for (int64_t id : spec.nodeOrder) {
    x.push_back(static_cast<double>(id));
    y.push_back(2.0 * static_cast<double>(id));
    z.push_back(3.0 * static_cast<double>(id));
  }
  ASSERT_GE(ex_put_coord(exoid, x.data(), y.data(), z.data()), 0);
  ASSERT_GE(ex_put_id_map(exoid, EX_NODE_MAP, spec.nodeOrder.data()), 0);
  for (const auto& [blockId, ids] : spec.blocks) {
    ASSERT_GE(ex_put_block(exoid, EX_ELEM_BLOCK, blockId, "SPHERE",
                           static_cast<int64_t>(ids.size()), 1, 0, 0, 0),
              0);
    std::vector<int64_t> conn;  // element id e uses the node with id e
    for (int64_t id : ids) {
      conn.push_back(std::find(spec.nodeOrder.begin(), spec.nodeOrder.end(), id) -
                     spec.nodeOrder.begin() + 1);
    }
    ASSERT_GE(ex_put_conn(exoid, EX_ELEM_BLOCK, blockId, conn.data(), nullptr, nullptr), 0);
  }
  ASSERT_GE(ex_put_id_map(exoid, EX_ELEM_MAP, elementIds.data()), 0);
  const auto putNames = [&](ex_entity_type type, const std::vector<std::string>& names) {
    if (names.empty()) return;
    ASSERT_GE(ex_put_variable_param(exoid, type, static_cast<int>(names.size())), 0);
    std::vector<char*> pointers;
    for (const auto& n : names) pointers.push_back(const_cast<char*>(n.c_str()));
    ASSERT_GE(ex_put_variable_names(exoid, type, static_cast<int>(names.size()), pointers.data()),
              0);
  };
  putNames(EX_NODAL, spec.nodal);
  putNames(EX_ELEM_BLOCK, spec.element);
  putNames(EX_GLOBAL, spec.global);
  if (!spec.element.empty()) {
    std::vector<int> truth(spec.blocks.size() * spec.element.size(), 1);
    ASSERT_GE(ex_put_truth_table(exoid, EX_ELEM_BLOCK, static_cast<int>(spec.blocks.size()),
                                 static_cast<int>(spec.element.size()), truth.data()),
              0);
  }
  for (int s = 1; s <= spec.steps; ++s) {
    const double time = 0.5 * (s - 1);
    ASSERT_GE(ex_put_time(exoid, s, &time), 0);
    for (std::size_t v = 0; v < spec.nodal.size(); ++v) {
      std::vector<double> values;
      for (int64_t id : spec.nodeOrder) values.push_back(spec.nodalValue(id, s) + v);
      ASSERT_GE(ex_put_var(exoid, s, EX_NODAL, static_cast<int>(v + 1), 1, numNodes, values.data()),
                0);
    }
    for (std::size_t v = 0; v < spec.element.size(); ++v) {
      for (const auto& [blockId, ids] : spec.blocks) {
        std::vector<double> values;
        for (int64_t id : ids) values.push_back(spec.elementValue(id, s) + v);
        ASSERT_GE(ex_put_var(exoid, s, EX_ELEM_BLOCK, static_cast<int>(v + 1), blockId,
                             static_cast<int64_t>(ids.size()), values.data()),
                  0);
      }
    }
    if (!spec.global.empty()) {
      std::vector<double> values(spec.global.size(), 10.0 * s);
      ASSERT_GE(ex_put_glob_vars(exoid, s, static_cast<int>(values.size()), values.data()), 0);
    }
  }
  ASSERT_EQ(ex_close(exoid), 0);
}

TestResults twoBlocks() {
  TestResults r;
  r.blocks = {{1, {1, 2, 3}}, {2, {4, 5}}};
  r.nodeOrder = {1, 2, 3, 4, 5};
  return r;
}

const CompSpec kStrict = peridot::parseCompText(
    "DEFAULT TOLERANCE absolute 1e-12\nCOORDINATES absolute 0\nTIME STEPS absolute 0\n"
    "NODAL VARIABLES\nELEMENT VARIABLES\nGLOBAL VARIABLES\n",
    "strict");

TEST(ExodusCompare, MatchesByIdWhateverTheOrder) {
  TestResults a = twoBlocks();
  TestResults b = twoBlocks();
  b.blocks = {{2, {5, 4}}, {1, {3, 1, 2}}};  // blocks and elements reordered
  b.nodeOrder = {4, 2, 5, 1, 3};
  TempFile fa(tempPath("a.e")), fb(tempPath("b.e"));
  writeResults(fa.path, a);
  writeResults(fb.path, b);
  const auto ra = peridot::readExodusResults(fa.path);
  const auto rb = peridot::readExodusResults(fb.path);
  EXPECT_EQ(rb.elementIds, (std::vector<long long>{5, 4, 3, 1, 2}));
  EXPECT_EQ(rb.elementBlock, (std::vector<long long>{2, 2, 1, 1, 1}));
  const auto report = peridot::compareExodusResults(rb, ra, kStrict);
  EXPECT_TRUE(report.passed()) << printed(report);
  // 3 coordinates x 5 nodes, 3 times, 3 steps x (5 nodal + 5 element + 1 global).
  EXPECT_EQ(report.valuesCompared(), 15u + 3u + 33u);

  // One element value off, in the reordered file.
  b.elementValue = [](int64_t id, int s) {
    return 1.0 / (id + s) + (id == 4 && s == 2 ? 1e-6 : 0);
  };
  writeResults(fb.path, b);
  const auto off = peridot::compareExodusResults(peridot::readExodusResults(fb.path), ra, kStrict);
  EXPECT_EQ(off.failures(), 1u);
  const auto* v = findReport(off, "element", "Damage");
  ASSERT_NE(v, nullptr);
  ASSERT_EQ(v->shown.size(), 1u);
  EXPECT_EQ(v->shown[0].id, 4);
  EXPECT_EQ(v->shown[0].step, 2);
  EXPECT_DOUBLE_EQ(v->shown[0].time, 0.5);
}

TEST(ExodusCompare, ReportsStructuralMismatches) {
  TestResults gold = twoBlocks();
  TestResults result = twoBlocks();
  result.blocks = {{1, {1, 2, 3}}, {2, {4, 6}}};  // element 5 missing, 6 extra
  result.nodeOrder = {1, 2, 3, 4, 6};
  result.nodal = {"VelocityX"};  // DisplacementX missing
  result.steps = 2;              // one step short
  TempFile fg(tempPath("gold.e")), fr(tempPath("result.e"));
  writeResults(fg.path, gold);
  writeResults(fr.path, result);
  const auto report = peridot::compareExodusResults(peridot::readExodusResults(fr.path),
                                                    peridot::readExodusResults(fg.path), kStrict);
  EXPECT_FALSE(report.passed());
  const auto has = [&](const std::string& part) {
    return std::any_of(report.problems.begin(), report.problems.end(),
                       [&](const std::string& p) { return p.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(has("gold nodes missing from the result: ids 5")) << printed(report);
  EXPECT_TRUE(has("result nodes not in the gold: ids 6"));
  EXPECT_TRUE(has("gold elements missing from the result: ids 5"));
  EXPECT_TRUE(has("nodal variable \"DisplacementX\" is missing from the result"));
  EXPECT_TRUE(has("the result has 2 time steps, the gold 3"));
  EXPECT_EQ(report.failures(), 0u);  // the common ids and steps agree

  // A variable the .comp lists but the gold lacks.
  const CompSpec listing =
      peridot::parseCompText("ELEMENT VARIABLES absolute 1\n\tNoSuchThing\n", "x.comp");
  const auto g = peridot::readExodusResults(fg.path);
  const auto r2 = peridot::compareExodusResults(g, g, listing);
  ASSERT_EQ(r2.problems.size(), 1u);
  EXPECT_NE(r2.problems[0].find("NoSuchThing"), std::string::npos);
  // Only the listed element variable is compared: no "Damage" report.
  EXPECT_EQ(findReport(r2, "element", "Damage"), nullptr);
  EXPECT_EQ(findReport(r2, "nodal", "DisplacementX"), nullptr);  // no NODAL section: none
}

TEST(ExodusCompare, UnreadableFilesThrow) {
  expectInputError([] { peridot::readExodusResults("/nonexistent/r.e"); },
                   {"cannot open Exodus file \"/nonexistent/r.e\"", "No such file"});
  std::ifstream in(kCases + "/WaveInBar/WaveInBar_gold.e", std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  TempFile cut(tempPath("cut.e"));
  {
    std::ofstream out(cut.path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  expectInputError([&] { peridot::readExodusResults(cut.path); }, {cut.path, "truncated"});
}

}  // namespace
