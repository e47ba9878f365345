// Atomic writes: the target gets the whole content or stays as it was; no temporary is left.
#include "pak/io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "pak/error.hpp"

namespace fs = std::filesystem;

namespace {

// A fresh folder per test, removed afterwards (tests may run in parallel under ctest -j).
class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("pak-atomic-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::permissions(folder_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(folder_, ignored);
  }
  std::string file(const std::string& name) const { return (folder_ / name).string(); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder_)) names.push_back(entry.path().filename().string());
    return names;
  }
  static std::string contentsOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }
  fs::path folder_;
};

TEST_F(AtomicFileTest, WritesTheContentsAndLeavesNoTemporary) {
  std::string path = file("out.svg");
  std::string contents("<svg/>\n\0binary\xff", 16);
  pak::writeFileAtomically(path, contents);
  EXPECT_EQ(contentsOf(path), contents);
  EXPECT_EQ(entries(), std::vector<std::string>{"out.svg"});
}

TEST_F(AtomicFileTest, ReplacesAnExistingFile) {
  std::string path = file("out.txt");
  pak::writeFileAtomically(path, "first version, longer than the second");
  pak::writeFileAtomically(path, "second");
  EXPECT_EQ(contentsOf(path), "second");
  EXPECT_EQ(entries().size(), 1u);
}

TEST_F(AtomicFileTest, WritesAnEmptyFile) {
  std::string path = file("empty");
  pak::writeFileAtomically(path, "");
  EXPECT_TRUE(fs::exists(path));
  EXPECT_EQ(fs::file_size(path), 0u);
}

TEST_F(AtomicFileTest, MissingFolderIsAnInputErrorNamingThePath) {
  std::string path = file("no/such/folder/out.png");
  try {
    pak::writeFileAtomically(path, "data");
    FAIL() << "expected InputError";
  } catch (const pak::InputError& error) {
    std::string message = error.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(AtomicFileTest, TargetThatIsAFolderIsAnInputError) {
  fs::create_directories(folder_ / "taken");
  EXPECT_THROW(pak::writeFileAtomically(file("taken"), "data"), pak::InputError);
  EXPECT_TRUE(fs::is_directory(folder_ / "taken"));
  EXPECT_EQ(entries(), std::vector<std::string>{"taken"});
}

TEST_F(AtomicFileTest, ParentThatIsAFileIsAnInputError) {
  pak::writeFileAtomically(file("plain"), "x");
  EXPECT_THROW(pak::writeFileAtomically(file("plain/out.svg"), "data"), pak::InputError);
  EXPECT_EQ(contentsOf(file("plain")), "x");
}

TEST_F(AtomicFileTest, ReadOnlyFolderIsAnInputErrorAndKeepsTheOldFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: permission bits do not stop root from writing";
  std::string path = file("kept.txt");
  pak::writeFileAtomically(path, "old");
  fs::permissions(folder_, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  EXPECT_THROW(pak::writeFileAtomically(path, "new"), pak::InputError);
  fs::permissions(folder_, fs::perms::owner_all, fs::perm_options::add);
  EXPECT_EQ(contentsOf(path), "old");
  EXPECT_EQ(entries().size(), 1u);
}

TEST_F(AtomicFileTest, EmptyPathIsAnInputError) { EXPECT_THROW(pak::writeFileAtomically("", "x"), pak::InputError); }

TEST_F(AtomicFileTest, TemporaryLivesBesideTheTargetAndIsUnique) {
  std::string path = file("image.png");
  std::string a = pak::temporaryPathFor(path);
  std::string b = pak::temporaryPathFor(path);
  EXPECT_NE(a, b);
  EXPECT_EQ(fs::path(a).parent_path(), folder_);
  EXPECT_NE(a, path);
  EXPECT_FALSE(fs::exists(a));  // only a name: the caller creates the file
}

TEST_F(AtomicFileTest, CommitMovesTheTemporaryIntoPlace) {
  std::string path = file("image.png");
  std::string temporary = pak::temporaryPathFor(path);
  std::ofstream(temporary) << "pixels";
  pak::commitTemporary(temporary, path);
  EXPECT_EQ(contentsOf(path), "pixels");
  EXPECT_EQ(entries(), std::vector<std::string>{"image.png"});
}

TEST_F(AtomicFileTest, FailedCommitRemovesTheTemporary) {
  std::string temporary = pak::temporaryPathFor(file("image.png"));
  std::ofstream(temporary) << "pixels";
  EXPECT_THROW(pak::commitTemporary(temporary, file("gone/image.png")), pak::InputError);
  EXPECT_TRUE(entries().empty());
}

TEST_F(AtomicFileTest, ConcurrentWritersNeverInterleave) {
  // Eight threads race to write the same file; the survivor must be one writer's whole text.
  std::string path = file("shared.txt");
  std::vector<std::string> texts;
  for (int i = 0; i < 8; ++i) texts.push_back(std::string(100000, static_cast<char>('a' + i)));
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&, i] {
      for (int round = 0; round < 5; ++round) pak::writeFileAtomically(path, texts[i]);
    });
  for (auto& thread : threads) thread.join();
  std::string result = contentsOf(path);
  EXPECT_NE(std::find(texts.begin(), texts.end(), result), texts.end());
  EXPECT_EQ(entries(), std::vector<std::string>{"shared.txt"});
}

}  // namespace
