// SPDX-License-Identifier: MIT
#include "cli.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace e2d::validation {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

struct Cli {
    int status = -1;
    std::string out;
    std::string err;
};

Cli run(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    Cli c;
    c.status = runCli(args, out, err);
    c.out = out.str();
    c.err = err.str();
    return c;
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("e2d_cli_test_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    std::string out() const { return (dir_ / "out").string(); }

    fs::path dir_;
};

// A ball dropped from 1.25 m with e = 0.5 rebounds to 0.3125 m.
const char* kDrop = R"({"family": "restitution", "duration": 2.0,
  "bodies": [
    {"type": "static", "position": [0, -1], "shape": {"type": "box", "halfExtents": [5, 1], "restitution": 0.5}},
    {"position": [0, 1.75], "tag": "ball", "shape": {"type": "circle", "radius": 0.5, "restitution": 0.5}}],
  "checks": [{"type": "bounceHeight", "body": "ball", "height": 1.25, "restY": 0.5,
              "restitution": RESTITUTION, "tolerance": 0.05}]})";

std::string drop(const std::string& restitution) {
    std::string text = kDrop;
    text.replace(text.find("RESTITUTION"), 11, restitution);
    return text;
}

TEST_F(CliTest, PassingScenarioExitsZeroAndWritesTheReport) {
    const Cli c = run({"--scenario", write("ok.json", drop("0.5")), "--out", out()});
    EXPECT_EQ(c.status, kExitPassed) << c.err << c.out;
    EXPECT_THAT(c.out, HasSubstr(" baseline runs passed"));
    EXPECT_THAT(c.out, Not(HasSubstr("FAIL")));
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / "report.html"));
    std::ifstream json(dir_ / "out" / "report.json");
    const nlohmann::json j = nlohmann::json::parse(json);
    EXPECT_TRUE(j.at("passed").get<bool>());
}

TEST_F(CliTest, FailedCheckExitsOneAndStillWritesTheReport) {
    // Judged against e = 0.9 (0.81 * 1.25 = 1.01 m), the same drop fails.
    const Cli c = run({"--scenario", write("bad.json", drop("0.9")), "--out", out()});
    EXPECT_EQ(c.status, kExitFailed) << c.err;
    EXPECT_THAT(c.out, HasSubstr("FAIL  bad [box2d]"));
    std::ifstream json(dir_ / "out" / "report.json");
    EXPECT_FALSE(nlohmann::json::parse(json).at("passed").get<bool>());
}

TEST_F(CliTest, InvalidScenarioExitsTwoNamingThePath) {
    std::string text = drop("0.5");
    text.replace(text.find("\"radius\": 0.5"), 13, "\"radius\": -1");
    const std::string file = write("invalid.json", text);
    const Cli c = run({"--scenario", file, "--out", out()});
    EXPECT_EQ(c.status, kExitBadInput);
    EXPECT_THAT(c.err, HasSubstr(file + ": bodies[1].shape.radius: must be > 0, got -1"));
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CliTest, UsageErrorsExitTwo) {
    EXPECT_EQ(run({}).status, kExitBadInput);
    EXPECT_EQ(run({"--bogus"}).status, kExitBadInput);
    EXPECT_EQ(run({"--all", "--quick"}).status, kExitBadInput);
    EXPECT_EQ(run({"--quick", "--jobs", "0"}).status, kExitBadInput);
    EXPECT_EQ(run({"--quick", "--sweep", "huge"}).status, kExitBadInput);
    const Cli engines = run({"--quick", "--engines", "havok"});
    EXPECT_EQ(engines.status, kExitBadInput);
    EXPECT_THAT(engines.err, HasSubstr("\"havok\" is not built in"));
    const Cli missing = run({"--scenario", "no_such_scenario"});
    EXPECT_EQ(missing.status, kExitBadInput);
    EXPECT_THAT(missing.err, HasSubstr("no_such_scenario: no such file"));
}

TEST_F(CliTest, HelpAndListExitZero) {
    const Cli help = run({"--help"});
    EXPECT_EQ(help.status, kExitPassed);
    EXPECT_THAT(help.out, HasSubstr("--scenario"));
    const Cli list = run({"--list"});
    EXPECT_EQ(list.status, kExitPassed);
    EXPECT_THAT(list.out, HasSubstr("pyramid_100  [stacking]"));
}

TEST_F(CliTest, ScenarioByName) {
    const Cli c = run({"--scenario", "elastic_impact", "--engines", "box2d", "--out", out()});
    EXPECT_EQ(c.status, kExitPassed) << c.out << c.err;
    EXPECT_THAT(c.out, HasSubstr("1/1 baseline runs passed"));
}

} // namespace
} // namespace e2d::validation
