// The main of a fuzz harness built without libFuzzer (a gcc build): feeds
// every file of the folders (or files) on its command line to the harness's
// LLVMFuzzerTestOneInput, in name order, and names each before it runs, so a
// crash or an escaped exception points at its input. Exit 0 when every input
// was read or refused cleanly; this is the corpus test `make test` runs.
#include "fuzz/harness_input.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <vector>

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg = argv[i];
    if (std::filesystem::is_directory(arg)) {
      for (const auto& entry : std::filesystem::directory_iterator(arg))
        if (entry.is_regular_file()) inputs.push_back(entry.path());
    } else {
      inputs.push_back(arg);
    }
  }
  std::sort(inputs.begin(), inputs.end());
  if (inputs.empty()) {
    std::fprintf(stderr, "usage: %s CORPUS_FOLDER_OR_FILE...: no input files given or found\n", argv[0]);
    return 2;
  }
  for (const auto& path : inputs) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: escaped the reader: %s\n", path.string().c_str(), e.what());
      return 1;
    }
  }
  std::printf("%zu inputs read or refused cleanly\n", inputs.size());
  return 0;
}
