// A small, deterministic mutation fuzzer that drives an LLVMFuzzerTestOneInput target when
// libFuzzer is not available (g++ builds, CI). It runs each seed file unchanged, every
// truncation on a coarse grid, then random mutations for a bounded time. Built with ASan and
// UBSan: a crash or report aborts the run, and the input that caused it is saved first.
#include <sanitizer/common_interface_defs.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

std::vector<uint8_t> g_current;

void saveCurrentInput() {
  const char* name = "fuzz-crash-input.bin";
  std::ofstream out(name, std::ios::binary);
  out.write(reinterpret_cast<const char*>(g_current.data()), static_cast<std::streamsize>(g_current.size()));
  std::fprintf(stderr, "mutation_driver: failing input (%zu bytes) saved to %s\n", g_current.size(), name);
}

void run(const std::vector<uint8_t>& input) {
  g_current = input;
  try {
    LLVMFuzzerTestOneInput(g_current.data(), g_current.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mutation_driver: target threw a non-hdprior exception: %s\n", e.what());
    saveCurrentInput();
    std::exit(1);
  }
}

class Mutator {
 public:
  explicit Mutator(uint64_t seed) : rng_(seed) {}

  std::vector<uint8_t> mutate(std::vector<uint8_t> d) {
    const int count = 1 + int(rng_() % 6);
    for (int i = 0; i < count && !d.empty(); ++i) mutateOnce(d);
    return d;
  }

 private:
  size_t pick(size_t n) { return n == 0 ? 0 : size_t(rng_() % n); }

  // Half of the mutations land near the start or the end, where headers and footers are.
  size_t position(const std::vector<uint8_t>& d) {
    const size_t n = d.size();
    switch (rng_() % 4) {
      case 0: return pick(std::min<size_t>(n, 512));
      case 1: return n - 1 - pick(std::min<size_t>(n, 4096));
      default: return pick(n);
    }
  }

  void mutateOnce(std::vector<uint8_t>& d) {
    static const int64_t interesting[] = {0, 1, -1, 2, 7, 8, 16, 64, 127, 128, 255, 256, 0x7fff, 0xffff, 0x7fffffff,
                                          int64_t(0x80000000), int64_t(0xffffffff), INT64_MAX, INT64_MIN};
    static const char tokens[] = "{}[]\",:-.eE0123456789 ntrufalse";
    const size_t pos = position(d);
    switch (rng_() % 8) {
      case 0: d[pos] ^= uint8_t(1u << (rng_() % 8)); break;
      case 1: d[pos] = uint8_t(rng_()); break;
      case 2: {
        const int64_t v = interesting[pick(std::size(interesting))];
        const size_t width = size_t(1) << (rng_() % 4);
        if (pos + width <= d.size()) std::memcpy(&d[pos], &v, width);
        break;
      }
      case 3: d.resize(pick(d.size())); break;
      case 4: d.erase(d.begin() + long(pos), d.begin() + long(std::min(d.size(), pos + 1 + pick(64)))); break;
      case 5: {
        const size_t from = pick(d.size()), len = std::min(d.size() - from, 1 + pick(64));
        const std::vector<uint8_t> chunk(d.begin() + long(from), d.begin() + long(from + len));
        d.insert(d.begin() + long(pos), chunk.begin(), chunk.end());
        break;
      }
      case 6: d[pos] = uint8_t(tokens[pick(sizeof(tokens) - 1)]); break;
      default: d.insert(d.begin() + long(pos), uint8_t(tokens[pick(sizeof(tokens) - 1)])); break;
    }
  }

  std::mt19937_64 rng_;
};

std::vector<uint8_t> readFile(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "mutation_driver: cannot read seed %s\n", path);
    std::exit(2);
  }
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 10;
  uint64_t seed = 1;
  std::vector<std::vector<uint8_t>> seeds;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seconds" && i + 1 < argc) {
      seconds = std::stod(argv[++i]);
    } else if (a == "--seed" && i + 1 < argc) {
      seed = std::stoull(argv[++i]);
    } else {
      seeds.push_back(readFile(argv[i]));
    }
  }
  if (seeds.empty()) {
    std::fprintf(stderr, "usage: %s [--seconds S] [--seed N] SEED_FILE...\n", argv[0]);
    return 2;
  }
  __sanitizer_set_death_callback(saveCurrentInput);

  size_t runs = 0;
  for (const auto& s : seeds) {
    run(s);
    const size_t step = std::max<size_t>(1, s.size() / 200);
    for (size_t len = 0; len < s.size(); len += step, ++runs) run(std::vector<uint8_t>(s.begin(), s.begin() + long(len)));
  }
  Mutator mutator(seed);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    run(mutator.mutate(seeds[runs % seeds.size()]));
    ++runs;
  }
  std::printf("mutation_driver: %zu inputs, no crash, no sanitizer report\n", runs);
  return 0;
}
