// The Restart deck entry in both of Peridigm's forms (bool, list) and Peridot's cadence keys, and
// the deck hash that decides whether a checkpoint belongs to a deck: it must ignore what a
// continuation deck changes and see everything else.
#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "deck/Deck.hpp"
#include "deck/RunConfig.hpp"

namespace peridot {
namespace {

// A minimal valid XML deck; `extra` goes at the top level, `stretch` and the times vary.
std::string xmlDeck(const std::string& extra, double initial = 0.0, double final = 1.0e-5,
                    const std::string& output = "out", const std::string& stretch = "0.002") {
  return R"(<ParameterList name="Peridigm">
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="PdQuickGrid"/>
    <ParameterList name="TensorProduct3DMeshGenerator">
      <Parameter name="X Origin" type="double" value="0.0"/>
      <Parameter name="Y Origin" type="double" value="0.0"/>
      <Parameter name="Z Origin" type="double" value="0.0"/>
      <Parameter name="X Length" type="double" value="1.0"/>
      <Parameter name="Y Length" type="double" value="1.0"/>
      <Parameter name="Z Length" type="double" value="1.0"/>
      <Parameter name="Number Points X" type="int" value="4"/>
      <Parameter name="Number Points Y" type="int" value="4"/>
      <Parameter name="Number Points Z" type="int" value="4"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="M">
      <Parameter name="Material Model" type="string" value="Elastic Bond Based"/>
      <Parameter name="Density" type="double" value="7800.0"/>
      <Parameter name="Bulk Modulus" type="double" value="1.0e9"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Damage Models">
    <ParameterList name="D">
      <Parameter name="Damage Model" type="string" value="Critical Stretch"/>
      <Parameter name="Critical Stretch" type="double" value=")" +
         stretch + R"("/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="B">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="M"/>
      <Parameter name="Damage Model" type="string" value="D"/>
      <Parameter name="Horizon" type="double" value="0.6"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value=")" +
         std::to_string(initial) + R"("/>
    <Parameter name="Final Time" type="double" value=")" +
         std::to_string(final) + R"("/>
    <ParameterList name="Verlet">
      <Parameter name="Fixed dt" type="double" value="1.0e-7"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value=")" +
         output + R"("/>
    <Parameter name="Output Frequency" type="int" value="10"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
    </ParameterList>
  </ParameterList>
)" + extra +
         "</ParameterList>\n";
}

RunConfig read(const std::string& xml) { return readRunConfig(*parseDeck(xml, "xml")); }

TEST(RestartConfig, OffByDefaultAndWithFalse) {
  EXPECT_FALSE(read(xmlDeck("")).restart.enabled);
  EXPECT_FALSE(
      read(xmlDeck(R"(<Parameter name="Restart" type="bool" value="false"/>)")).restart.enabled);
}

TEST(RestartConfig, PeridigmsBoolAndListForms) {
  const RunConfig flag = read(xmlDeck(R"(<Parameter name="Restart" type="bool" value="true"/>)"));
  EXPECT_TRUE(flag.restart.enabled);
  EXPECT_EQ(flag.restart.checkpointFrequency, 0);
  EXPECT_EQ(flag.restart.name, "peridot.checkpoint");
  const RunConfig list = read(xmlDeck(R"(<ParameterList name="Restart">
    <Parameter name="Restart" type="bool" value="true"/>
  </ParameterList>)"));
  EXPECT_TRUE(list.restart.enabled);
}

TEST(RestartConfig, CadenceKeys) {
  const RunConfig c = read(xmlDeck(R"(<ParameterList name="Restart">
    <Parameter name="Checkpoint Frequency" type="int" value="500"/>
    <Parameter name="Checkpoint Interval" type="double" value="30"/>
    <Parameter name="Wall Clock Limit" type="double" value="710"/>
    <Parameter name="Checkpoint Directory" type="string" value="ckpt"/>
    <Parameter name="Checkpoint Name" type="string" value="run.ckpt"/>
  </ParameterList>)"));
  EXPECT_TRUE(c.restart.enabled);  // the list alone turns restart on
  EXPECT_EQ(c.restart.checkpointFrequency, 500);
  EXPECT_DOUBLE_EQ(c.restart.checkpointInterval, 30);
  EXPECT_DOUBLE_EQ(c.restart.wallClockLimit, 710);
  EXPECT_EQ(c.restart.directory, "ckpt");
  EXPECT_EQ(c.restart.name, "run.ckpt");
}

TEST(RestartConfig, RejectsUnknownAndBadKeys) {
  auto message = [](const std::string& extra) {
    try {
      read(xmlDeck(extra));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(R"(<ParameterList name="Restart">
    <Parameter name="Checkpoint Every" type="int" value="5"/></ParameterList>)")
                .find("Restart -> Checkpoint Every: unknown parameter"),
            std::string::npos);
  EXPECT_NE(message(R"(<ParameterList name="Restart">
    <Parameter name="Wall Clock Limit" type="double" value="-1"/></ParameterList>)")
                .find("Restart -> Wall Clock Limit"),
            std::string::npos);
  EXPECT_NE(message(R"(<ParameterList name="Restart">
    <Parameter name="Checkpoint Name" type="string" value="a/b"/></ParameterList>)")
                .find("Restart -> Checkpoint Name"),
            std::string::npos);
}

TEST(RestartConfig, DeckHashIgnoresWhatAContinuationChanges) {
  const auto base = read(xmlDeck("")).restart.deckHash;
  // Peridigm's second deck: other times, another output file, and a Restart entry.
  EXPECT_EQ(base, read(xmlDeck(R"(<Parameter name="Restart" type="bool" value="true"/>)", 5.0e-6,
                               2.0e-5, "part2"))
                      .restart.deckHash);
  // Anything else is another problem.
  EXPECT_NE(base, read(xmlDeck("", 0.0, 1.0e-5, "out", "0.003")).restart.deckHash);
}

}  // namespace
}  // namespace peridot
