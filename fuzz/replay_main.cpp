// Replay driver for the fuzz targets without libFuzzer: runs
// LLVMFuzzerTestOneInput on every file named on the command line, and on
// every regular file under each directory argument (recursively, sorted by
// path so the order is deterministic). An empty or missing directory runs the
// empty input once instead. Prints how many inputs ran and exits 0; a
// failing oracle aborts (that, or a sanitizer report, is the failure).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace fs = std::filesystem;

namespace {

// Run one input from an exactly sized heap copy, so that a sanitizer build
// sees reads past its end.
void run(const std::vector<char>& bytes) {
  std::unique_ptr<uint8_t[]> copy(new uint8_t[bytes.size() ? bytes.size() : 1]);
  if (!bytes.empty()) std::memcpy(copy.get(), bytes.data(), bytes.size());
  LLVMFuzzerTestOneInput(copy.get(), bytes.size());
}

bool read_file(const fs::path& p, std::vector<char>& out) {
  std::ifstream f(p, std::ios::binary);
  if (!f) return false;
  out.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  return !f.bad();
}

}  // namespace

int main(int argc, char** argv) {
  size_t ran = 0;
  if (argc < 2) {
    std::printf("replay: no inputs given: running the empty input once\n");
    run({});
    std::printf("replay: ran 1 input\n");
    return 0;
  }
  for (int a = 1; a < argc; ++a) {
    const fs::path arg(argv[a]);
    std::error_code ec;
    std::vector<fs::path> files;
    if (fs::is_directory(arg, ec)) {
      for (auto it = fs::recursive_directory_iterator(arg, ec);
           !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file(ec)) files.push_back(it->path());
      std::sort(files.begin(), files.end());
      if (files.empty()) {
        std::printf("replay: %s is empty: running the empty input once\n", argv[a]);
        run({});
        ++ran;
        continue;
      }
    } else if (fs::is_regular_file(arg, ec)) {
      files.push_back(arg);
    } else {
      std::printf("replay: %s does not exist: running the empty input once\n", argv[a]);
      run({});
      ++ran;
      continue;
    }
    for (const fs::path& p : files) {
      std::vector<char> bytes;
      if (!read_file(p, bytes)) {
        std::fprintf(stderr, "replay: cannot read %s\n", p.c_str());
        return 2;
      }
      std::fprintf(stderr, "replay: %s (%zu bytes)\n", p.c_str(), bytes.size());
      run(bytes);
      ++ran;
    }
  }
  std::printf("replay: ran %zu input%s\n", ran, ran == 1 ? "" : "s");
  return 0;
}
