// SPDX-License-Identifier: MIT
// GLFW's own mapping database, through glfwUpdateGamepadMappings (glfwInit needs a display:
// CTest runs this through scripts/with-display.sh).
#include <e2d/core/error.hpp>
#include <e2d/input/gamepad_mappings.hpp>

#include <GLFW/glfw3.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace e2d::input {
namespace {

using ::testing::ElementsAre;

const std::string kGood =
    "03000000de280000ff11000001000000,Test Pad,a:b0,b:b1,x:b2,y:b3,leftx:a0,lefty:a1,"
    "dpup:h0.1,lefttrigger:a2,platform:Linux,";
const std::string kGood2 =
    "05000000de280000ff11000001000000,Test Pad 2,a:b1,b:b0,rightx:a3~,righttrigger:+a5,";

// Owns GLFW's initialisation for one test.
class Glfw : public ::testing::Test {
protected:
    void SetUp() override {
        // Xvfb resets when its last client leaves (the previous test's glfwTerminate) and
        // refuses connections for a moment while it does: retry for up to 2 s.
        bool initialised = false;
        for (int attempt = 0; attempt < 40 && !initialised; ++attempt) {
            initialised = glfwInit() == GLFW_TRUE;
            if (!initialised) {
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
        }
        ASSERT_TRUE(initialised) << "glfwInit failed (no display?)";
        static_cast<void>(glfwGetError(nullptr));
    }
    void TearDown() override { glfwTerminate(); }
    static int lastGlfwError() { return glfwGetError(nullptr); }
};

TEST_F(Glfw, ValidMappingsLoad) {
    const MappingLoadResult r = loadGamepadMappings(kGood + "\n" + kGood2 + "\n");
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.loaded, 2);
    EXPECT_EQ(lastGlfwError(), GLFW_NO_ERROR);
}

TEST_F(Glfw, GlfwItselfAcceptsBadLinesWithoutFailing) {
    // Why the lines are checked first: GLFW returns true and at most raises an error code.
    EXPECT_EQ(glfwUpdateGamepadMappings("0300000,bad guid,a:b0\n"), GLFW_TRUE);
    EXPECT_EQ(lastGlfwError(), GLFW_INVALID_VALUE);
    EXPECT_EQ(glfwUpdateGamepadMappings("03000000de280000ff11000001000000,Name,zz:b1,a:q0,\n"),
              GLFW_TRUE);
    EXPECT_EQ(lastGlfwError(), GLFW_NO_ERROR);
}

TEST_F(Glfw, InvalidMappingsAreReportedAndNothingReachesGlfw) {
    const MappingLoadResult r = loadGamepadMappings(
        "0300000,bad guid,a:b0\n03000000de280000ff11000001000000,N\n", "bad.txt");
    EXPECT_EQ(r.loaded, 0);
    ASSERT_EQ(r.diagnostics.errors().size(), 2u);
    EXPECT_EQ(r.diagnostics.errors()[0].toString(),
              "bad.txt:1: GUID must be 32 hex digits, got '0300000'");
    EXPECT_EQ(r.diagnostics.errors()[1].toString(), "bad.txt:2: expected fields after the name");
    EXPECT_EQ(lastGlfwError(), GLFW_NO_ERROR); // GLFW would have raised GLFW_INVALID_VALUE
}

TEST_F(Glfw, MixedTextLoadsTheGoodLinesAndListsTheBadOnes) {
    const std::filesystem::path path =
        std::filesystem::path(::testing::TempDir()) / "e2d_input_mixed_mappings.txt";
    {
        std::ofstream out(path);
        out << "# pads\n"
            << kGood << "\nnot hex at all\n"
            << kGood2 << "\n"
            << "03000000de280000ff11000002000000,Win Pad,a:b0,platform:Windows,\n";
    }
    const MappingLoadResult r = loadGamepadMappingsFile(path);
    EXPECT_EQ(r.loaded, 2);
    EXPECT_EQ(r.otherPlatform, 1);
    ASSERT_EQ(r.diagnostics.errors().size(), 1u);
    EXPECT_EQ(r.diagnostics.errors()[0].line, 3);
    EXPECT_EQ(r.diagnostics.errors()[0].toString(),
              path.string() + ":3: GUID must be 32 hex digits, got 'not hex at all'");
    EXPECT_EQ(lastGlfwError(), GLFW_NO_ERROR);
    std::filesystem::remove(path);
}

TEST_F(Glfw, AMappingMadeAtRunTimeForAnUnmappedJoystickLoads) {
    const std::string line =
        makeGamepadMapping("03000000aaaa0000bbbb000001000000", "Garage Stick", "a:b3,leftx:a1,");
    const MappingLoadResult r = loadGamepadMappings(line);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.loaded, 1);
    EXPECT_EQ(lastGlfwError(), GLFW_NO_ERROR);
}

// A line GLFW can use once its output modifiers are left out loads, and warnings do not make
// the load fail.
TEST_F(Glfw, WarningsAreCountedApartFromErrors) {
    const std::string joyCon =
        "050000007e0500000620000001800000,Joy-Con (L),a:b0,b:b1,+leftx:h0.2,-leftx:h0.8,"
        "misc2:b12,zz:b3,platform:Linux,";
    const MappingLoadResult r = loadGamepadMappings(joyCon + "\n" + kGood + "\n", "db.txt");
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.loaded, 2);
    EXPECT_TRUE(r.diagnostics.ok());
    ASSERT_EQ(r.diagnostics.warnings().size(), 2u);
    EXPECT_EQ(r.diagnostics.warnings()[0].line, 1);
    EXPECT_EQ(r.diagnostics.warnings()[1].line, 1);
    EXPECT_EQ(lastGlfwError(), GLFW_NO_ERROR);
}

TEST(GlfwMissing, LoadingWithoutGlfwIsAClearError) {
    try {
        static_cast<void>(loadGamepadMappings(kGood));
        FAIL() << "no error";
    } catch (const core::Error& e) {
        EXPECT_STREQ(e.what(), "input::loadGamepadMappings(): GLFW is not initialised");
    }
    static_cast<void>(glfwGetError(nullptr));
    EXPECT_THROW(static_cast<void>(loadGamepadMappingsFile("/nonexistent/e2d/pads.txt")),
                 core::Error);
}

} // namespace
} // namespace e2d::input
