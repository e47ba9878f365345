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
using pak::testing::readWholeFile;
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

// A command that fails before writing anything: exactly "pak: error: <start>…" on one stderr
// line, exit code 2, and no C++ or library name (the parsers' own messages are reworded).
void expectOneLineError(const std::string& arguments, const std::string& start) {
  PakRun run = runPak(arguments);
  SCOPED_TRACE("pak " + arguments + "\nstderr: " + run.err);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  ASSERT_EQ(run.errLines().size(), 1u);
  EXPECT_EQ(run.err.rfind("pak: error: " + start, 0), 0u);
  for (const char* internal : {"json.exception", "std::", "stoi", "stod", "_M_", "CLI::", "Could not convert",
                               "basic_string", "what()"})
    EXPECT_EQ(run.err.find(internal), std::string::npos) << internal;
}

const std::string kPack = "pack -c examples/scene.svg -e examples/elements -q ";
const std::string kFlow = "flow examples/flow/koi.svg -e examples/flow/elements -q ";
const std::string kAnimate = "animate -c examples/animate/stars/disc.svg -a examples/animate/stars/stars.json -q ";

// Out of range, unreadable, unknown or missing: each error names the option as typed.
TEST(CliErrors, OptionErrorsNameTheOption) {
  ScratchFolder out("errors-options");
  const std::string o = "-o " + shellQuoted(out.file("out.svg")) + " ";
  const std::pair<std::string, std::string> cases[] = {
      {kPack + o + "--gap -1", "--gap: must be a positive number"},
      {kPack + o + "--k-edge -5", "--k-edge: must be a non-negative number"},
      {kPack + o + "--stall-window 0", "--stall-window: must be at least 1"},
      {kPack + o + "--preset stiff", "--preset: unknown preset \"stiff\""},
      {kPack + o + "--orientation sideways", "--orientation: 'sideways' is not one of"},
      {kFlow + o + "--stop-ratio 2", "--stop-ratio: must be in (0, 1]"},
      {kPack + o + "--count abc", "--count: cannot read 'abc' as an integer"},
      {kPack + o + "--gap wide", "--gap: 'wide' is not a length (a number, or a number with mm, cm, in, pt, px or %)"},
      {kPack + o + "--seed -1", "--seed: must be a non-negative integer"},
      {kPack + o + "--seed 99999999999999999999999", "--seed: must be at most"},
      {kPack + o + "--no-such-option 3", "--no-such-option: not an option of this command"},
      {"pack -e examples/elements " + o, "--container: is required"},
      {"pack -c examples/scene.svg " + o, "--elements: is required"},
      {"", "expected a command: "},
  };
  for (const auto& [arguments, start] : cases) expectOneLineError(arguments, start);
  EXPECT_TRUE(fs::is_empty(out.path()));
}

// Every output is checked before the run (render's too): a missing folder, an output that is
// an input, two outputs in one file. Nothing is written, the inputs are untouched, and no folder the run
// would have made (snapshots, animate's output) is made.
TEST(CliErrors, OutputsAreCheckedBeforeTheRun) {
  ScratchFolder out("errors-outputs");
  const std::string original = readWholeFile(std::string(PAK_SOURCE_DIR) + "/examples/scene.svg");
  ASSERT_FALSE(original.empty());
  const std::string scene = out.write("scene.svg", original);
  const std::string missing = out.file("no-such-folder") + "/r.json";
  const std::string o = out.file("o.svg"), snapshots = out.file("snapshots"), frames = out.file("frames");
  const std::pair<std::string, std::string> cases[] = {
      {kPack + "-o " + shellQuoted(o) + " --snapshots " + shellQuoted(snapshots) + " --report " + shellQuoted(missing),
       missing + ": cannot write: folder '" + out.file("no-such-folder") + "' does not exist"},
      {"pack -c " + shellQuoted(scene) + " -e examples/elements -q -o " + shellQuoted(scene),
       scene + ": -o would overwrite an input of this run"},
      {kPack + "-o " + shellQuoted(o) + " --png " + shellQuoted(o), o + ": given to both -o and --png"},
      {"render " + shellQuoted(scene) + " -o " + shellQuoted(scene), scene + ": -o would overwrite an input of this run"},
      {kFlow + "-o " + shellQuoted(o) + " --report " + shellQuoted(o), o + ": given to both -o and --report"},
      {kAnimate + "-o " + shellQuoted(frames) + " --report examples/animate/stars/stars.json",
       "examples/animate/stars/stars.json: --report would overwrite an input of this run"},
      {kAnimate + "-o " + shellQuoted(frames) + " --png " + shellQuoted(missing), missing + ": cannot write: folder"},
      {"metrics " + shellQuoted(scene) + " --json " + shellQuoted(scene), scene + ": --json would overwrite an input of this run"},
      {"metrics " + shellQuoted(scene) + " --plot " + shellQuoted(o) + " --csv " + shellQuoted(o), o + ": given to both"},
  };
  for (const auto& [arguments, start] : cases) expectOneLineError(arguments, start);
  EXPECT_EQ(readWholeFile(scene), original);
  EXPECT_FALSE(fs::exists(o));
  EXPECT_FALSE(fs::exists(snapshots));
  EXPECT_FALSE(fs::exists(frames));
}

// pak animate checks the forces it shares with pak pack under pack's names, and takes its old
// spellings, but not both at once.
TEST(CliErrors, AnimateOptionsUnderPackNames) {
  ScratchFolder out("errors-animate");
  const std::string animate = kAnimate + "-o " + shellQuoted(out.file("anim"));
  expectOneLineError(animate + " --cell-size 0", "--cell-size: must be a positive number");
  expectOneLineError(animate + " --edge -1", "--k-edge: must be a non-negative number");
  expectOneLineError(animate + " --edge 30 --k-edge 40", "--edge: the same option as --k-edge");
  expectOneLineError(animate + " --settle-iterations -1", "--settle-iterations: must not be negative");
  expectOneLineError(animate + " --settle-k-overlap -5", "--settle-k-overlap: must be a non-negative number");
  const std::string config = out.write("both.json", R"({"edge": 30, "k-edge": 40})");
  expectOneLineError(animate + " --config " + shellQuoted(config),
                     config + ": \"edge\" and \"k-edge\" are the same option");
}

TEST(CliErrors, BadConfigFilesNameTheFileAndLine) {
  ScratchFolder folder("errors-config");
  const std::string o = "-o " + shellQuoted(folder.file("out.svg")) + " --config ";
  struct Case {
    const char* name;
    const char* contents;
    const char* problem;  // after "FILE: "
  };
  const Case cases[] = {
      {"broken.json", "{\n  \"gap\": 12,\n  \"count\" 4\n}\n", "not valid JSON at line 3, column "},
      {"huge.json", R"({"gap": 1e999})", "not valid JSON: number overflow"},
      {"empty.json", "", "not valid JSON at line 1"},
      {"count.json", R"({"count": 99999999999})", "\"count\" is out of range"},
      {"seed.json", R"({"seed": -2})", "\"seed\" must be a non-negative integer"},
  };
  for (const Case& c : cases) {
    const std::string file = folder.write(c.name, c.contents);
    expectOneLineError(kPack + o + shellQuoted(file), file + ": " + c.problem);
  }
  // A value the file gives is checked as if typed: the error names the option.
  const std::string preset = folder.write("preset.json", R"({"preset": "stiff"})");
  expectOneLineError(kPack + o + shellQuoted(preset), "--preset: unknown preset \"stiff\"");
}

TEST(CliErrors, BadAnimationFileNamesTheFileAndLine) {
  ScratchFolder folder("errors-animation");
  const std::string script = folder.write("broken.json", "{\"elements\": [\n  {\"svg\": }\n]}\n");
  expectOneLineError("animate -c examples/animate/stars/disc.svg -q -o " + shellQuoted(folder.file("anim")) +
                         " -a " + shellQuoted(script),
                     script + ": not valid JSON at line 2, column ");
}

// A long bad value once overflowed the stack: the messages were read with std::regex, which
// recurses once per character (a fuzz finding, tests/fuzz/regressions/animation_script/).
TEST(CliErrors, LongBadValuesGiveOneShortLine) {
  ScratchFolder folder("errors-long");
  const std::string longWord(100'000, 'x');
  const std::string config = folder.write("long.json", "{\"gap\": \"" + longWord + "\x01\"}");
  const std::string o = "-o " + shellQuoted(folder.file("out.svg"));
  expectOneLineError(kPack + o + " --config " + shellQuoted(config), config + ": not valid JSON at line 1, column ");
  expectOneLineError(kPack + o + " " + longWord, "unexpected argument xxx");
  expectOneLineError(kPack + o + " --gap " + longWord, "--gap: ");
  const PakRun run = runPak(kPack + o + " " + longWord);
  EXPECT_LT(run.err.size(), 600u);
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
