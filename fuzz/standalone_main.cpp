//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A stand-in for libFuzzer's driver, for compilers without -fsanitize=fuzzer
// (g++): runs the harness on each file named on the command line, or on
// -runs=N random byte strings (0 to 256 bytes, std::mt19937_64 seeded by
// -seed=S).  Other -flags, which libFuzzer would take, are ignored.  Not
// coverage-guided: the CI's clang build links the real libFuzzer instead.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  unsigned long long runs = 1000, seed = 1;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("-runs=", 0) == 0) {
      runs = std::strtoull(a.c_str() + 6, nullptr, 10);
    } else if (a.rfind("-seed=", 0) == 0) {
      seed = std::strtoull(a.c_str() + 6, nullptr, 10);
    } else if (a.empty() || a[0] != '-') {
      files.push_back(a);
    }
  }
  if (!files.empty()) {
    for (const auto& f : files) {
      std::ifstream in(f, std::ios::binary);
      if (!in) {
        std::fprintf(stderr, "%s: cannot read %s\n", argv[0], f.c_str());
        return 2;
      }
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      std::printf("%s: ran %s\n", argv[0], f.c_str());
    }
    return 0;
  }
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> buf;
  for (unsigned long long r = 0; r < runs; ++r) {
    buf.resize(static_cast<std::size_t>(rng() % 257));
    for (auto& b : buf) b = static_cast<std::uint8_t>(rng());
    LLVMFuzzerTestOneInput(buf.data(), buf.size());
  }
  std::printf("Done %llu runs (random bytes, seed %llu)\n", runs, seed);
  return 0;
}
