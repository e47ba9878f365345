// `pak help [COMMAND]`, `pak -V`/`--version`, and an unknown command: what a new user types
// first. Help is the same text as `--help`, names the program `pak` (not the path it was run
// by), and a wrong command lists the right ones on one line.
#include <gtest/gtest.h>

#include <string>

#include "cli/run_pak.hpp"

using pak::testing::PakRun;
using pak::testing::runPak;

namespace {

const char* const kCommands[] = {"animate", "flow", "inspect", "metrics", "pack", "render"};

TEST(CliHelp, VersionHasAShortAndALongFlag) {
  for (const char* flag : {"-V", "--version"}) {
    PakRun run = runPak(flag);
    EXPECT_EQ(run.exitCode, 0) << flag << "\n" << run.err;
    EXPECT_EQ(run.out, std::string("pak ") + PAK_VERSION + "\n") << flag;
  }
}

TEST(CliHelp, HelpIsTheSameAsDashDashHelpAndNamesPak) {
  PakRun top = runPak("help");
  ASSERT_EQ(top.exitCode, 0) << top.err;
  EXPECT_EQ(top.out, runPak("--help").out);
  EXPECT_NE(top.out.find("Usage: pak [OPTIONS]"), std::string::npos) << top.out;
  for (const char* command : kCommands) {
    PakRun help = runPak(std::string("help ") + command);
    ASSERT_EQ(help.exitCode, 0) << command << "\n" << help.err;
    EXPECT_EQ(help.out, runPak(std::string(command) + " --help").out) << command;
    EXPECT_NE(help.out.find(std::string("Usage: pak ") + command), std::string::npos) << help.out;
    EXPECT_EQ(help.out.find(PAK_BINARY), std::string::npos) << "the build path leaks into --help";
  }
}

TEST(CliHelp, AnUnknownCommandListsTheKnownOnes) {
  for (const char* arguments : {"frobnicate", "help frobnicate", "frobnicate --help"}) {
    PakRun run = runPak(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments;
    EXPECT_TRUE(run.out.empty()) << run.out;
    ASSERT_EQ(run.errLines().size(), 1u) << run.err;
    EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("'frobnicate'"), std::string::npos) << run.err;
    for (const char* command : kCommands) EXPECT_NE(run.err.find(command), std::string::npos) << command;
  }
  PakRun extra = runPak("help flow pack");
  EXPECT_EQ(extra.exitCode, 2);
  EXPECT_EQ(extra.errLines().size(), 1u) << extra.err;
}

}  // namespace
