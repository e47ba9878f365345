// Runs a fuzz target's LLVMFuzzerTestOneInput on saved inputs, without libFuzzer, so that
// `make test` replays the corpus and every past finding with g++ and its sanitizers.
// Arguments: files, or folders whose files are replayed in name order. A folder that does not
// exist is skipped (a target with no regression yet has no folder); replaying nothing fails.
// A crash, a sanitizer report or an escaping exception ends the program; an input slower than
// kSlowSeconds is reported and fails the run, as a hang would under libFuzzer's -timeout.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

// Generous: the sanitizer build is several times slower than libFuzzer's, whose -timeout
// `make fuzz` sets to 10 s.
constexpr double kSlowSeconds = 60.0;

std::vector<fs::path> inputsOf(const std::vector<std::string>& arguments) {
  std::vector<fs::path> inputs;
  for (const std::string& argument : arguments) {
    std::error_code error;
    if (fs::is_directory(argument, error)) {
      std::vector<fs::path> files;
      for (const fs::directory_entry& entry : fs::directory_iterator(argument))
        if (entry.is_regular_file()) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      inputs.insert(inputs.end(), files.begin(), files.end());
    } else if (fs::exists(argument, error)) {
      inputs.emplace_back(argument);
    } else {
      std::fprintf(stderr, "replay: %s: not there, skipped\n", argument.c_str());
    }
  }
  return inputs;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<fs::path> inputs = inputsOf(std::vector<std::string>(argv + 1, argv + argc));
  if (inputs.empty()) {
    std::fprintf(stderr, "replay: no input to replay\n");
    return 1;
  }
  int slow = 0;
  for (const fs::path& input : inputs) {
    std::ifstream file(input, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (!file.good() && !file.eof()) {
      std::fprintf(stderr, "replay: %s: cannot read\n", input.c_str());
      return 1;
    }
    // Named first, so that a crash's report follows the input that caused it.
    std::fprintf(stderr, "replay: %s (%zu bytes)\n", input.c_str(), bytes.size());
    const auto start = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > kSlowSeconds) {
      std::fprintf(stderr, "replay: %s took %.1f s, over the %.0f s bound\n", input.c_str(), seconds, kSlowSeconds);
      ++slow;
    }
  }
  std::printf("replay: %zu inputs, %d over the time bound\n", inputs.size(), slow);
  return slow == 0 ? 0 : 1;
}
