// Bad input never crashes `pak`: every case gives exactly one stderr line
// "pak: error: <file>: <what and where>", exit code 2, nothing on stdout and no output file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/run_pak.hpp"

namespace fs = std::filesystem;
using pak::testing::PakRun;
using pak::testing::runPak;
using pak::testing::ScratchFolder;
using pak::testing::shellQuoted;

namespace {

constexpr const char* kSvgOpen = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)";

enum class Commands { InspectAndRender, InspectOnly };

// Checks the one-line error contract for `inspect` and `render`, and that render wrote nothing.
// Some inputs are bad only as a scene or an element (an open container outline, a flat
// element): `render` still draws those, as a viewer should.
void expectInputError(const std::string& file, const std::string& expectedWords = "",
                      Commands commands = Commands::InspectAndRender) {
  ScratchFolder out("errors-out");
  std::vector<std::string> names = {"inspect"};
  if (commands == Commands::InspectAndRender) names.push_back("render");
  for (const std::string& command : names) {
    std::string arguments = command + " " + shellQuoted(file);
    if (command == "render") arguments += " -o " + shellQuoted(out.file("out.png"));
    PakRun run = runPak(arguments);
    SCOPED_TRACE("pak " + arguments + "\nstderr: " + run.err);
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.out.empty()) << run.out;
    ASSERT_EQ(run.errLines().size(), 1u);
    EXPECT_EQ(run.err.rfind("pak: error: " + file + ":", 0), 0u);
    if (!expectedWords.empty()) {
      EXPECT_NE(run.err.find(expectedWords), std::string::npos);
    }
  }
  EXPECT_TRUE(fs::is_empty(out.path()));
}

TEST(CliErrors, MissingFile) {
  ScratchFolder folder("missing");
  expectInputError(folder.file("no-such-file.svg"));
}

TEST(CliErrors, FolderInsteadOfFile) {
  ScratchFolder folder("folder-input");
  fs::create_directories(folder.path() / "drawing.svg");
  expectInputError(folder.file("drawing.svg"));
}

TEST(CliErrors, UnreadableFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: file permissions cannot make a file unreadable";
  ScratchFolder folder("unreadable");
  std::string file = folder.write("secret.svg", std::string(kSvgOpen) + R"(<rect width="5" height="5"/></svg>)");
  fs::permissions(file, fs::perms::none);
  expectInputError(file);
}

TEST(CliErrors, NotXml) {
  ScratchFolder folder("not-xml");
  expectInputError(folder.write("notes.svg", "This is a shopping list, not a drawing.\n<<< eggs & milk\n"));
}

TEST(CliErrors, XmlButNotSvg) {
  ScratchFolder folder("not-svg");
  expectInputError(folder.write("page.svg", "<?xml version=\"1.0\"?>\n<html><body><p>hello</p></body></html>\n"),
                   "not an SVG");
}

TEST(CliErrors, SvgWithNoUsableShape) {
  ScratchFolder folder("no-shape");
  expectInputError(folder.write("empty.svg", std::string(kSvgOpen) + "<title>nothing here</title><text>hi</text></svg>"));
}

TEST(CliErrors, NaNCoordinate) {
  ScratchFolder folder("nan");
  expectInputError(folder.write("nan.svg", std::string(kSvgOpen) + R"(<rect x="nan" y="0" width="10" height="10"/></svg>)"));
}

TEST(CliErrors, AbsurdCoordinate) {
  ScratchFolder folder("absurd");
  expectInputError(folder.write("absurd.svg", std::string(kSvgOpen) + R"(<path d="M 0 0 L 1e300 0 L 0 10 Z"/></svg>)"));
}

TEST(CliErrors, UnclosedContainer) {
  ScratchFolder folder("unclosed");
  expectInputError(folder.write("unclosed.svg", std::string(kSvgOpen) +
                                                    R"(<g id="container"><path d="M 10 10 L 90 10 L 90 90 L 10 90" )"
                                                    R"(fill="none" stroke="black"/></g></svg>)"),
                   "", Commands::InspectOnly);
}

TEST(CliErrors, ZeroAreaElement) {
  ScratchFolder folder("zero-area");
  expectInputError(folder.write("flat.svg", std::string(kSvgOpen) + R"(<path d="M 10 10 L 50 50 L 90 90 Z"/></svg>)"),
                   "", Commands::InspectOnly);
}

TEST(CliErrors, PathFileWithGarbage) {
  ScratchFolder folder("garbage-path");
  expectInputError(folder.write("broken.path", "1\n0 1 0 10 10 50 10 banana 50 50 10\n"));
}

TEST(CliErrors, EmptyPathFile) {
  ScratchFolder folder("empty-path");
  expectInputError(folder.write("empty.path", ""));
}

TEST(CliErrors, UnknownOptionIsAUsageError) {
  PakRun run = runPak("inspect --no-such-option examples/scene.svg");
  EXPECT_EQ(run.exitCode, 2);
  ASSERT_FALSE(run.errLines().empty());
  EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
}

TEST(CliErrors, MissingArgumentIsAUsageError) {
  PakRun run = runPak("render examples/scene.svg");  // no -o
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
}

}  // namespace
