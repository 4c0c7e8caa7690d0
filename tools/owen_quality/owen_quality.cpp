// Is vkmc's Owen scrambling (sampler.h: a Laine-Karras hash of the reversed bits, pbrt-v4's FastOwenScrambler
// constants, the index shuffled by the same hash) as good as true Owen scrambling, where every bit of every point
// is flipped by an independent random bit of its prefix? Variance of the 16-, 64- and 256-point estimate of four 2D
// integrands over 20000 scramblings, against independent points, for: vkmc's pair as the kernels draw it, true
// Owen (a 64-bit hash of seed, level and prefix), and the hash without the index shuffle. docs/journal/cycles.md.
//   g++ -O2 -std=c++20 -Ishaders/shared tools/owen_quality/owen_quality.cpp -o build/owen_quality && build/owen_quality
#include "sampler.h"
#include <cstdio>
#include <cmath>
#include <vector>
#include <random>
using namespace vkmc::gpu;
// exact Owen scramble: flip bit k by a strong hash of (seed, k, prefix of k bits)
static uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}
uint trueOwen(uint v, uint seed) {
  uint out = 0;
  for (int k = 0; k < 32; k++) {
    uint prefix = k == 0 ? 0u : (v >> (32 - k));
    uint flip = mix64(((uint64_t)seed << 40) ^ ((uint64_t)k << 33) ^ prefix ^ 0x1234567ULL * (k + 1)) & 1;
    uint bit = (v >> (31 - k)) & 1;
    out |= ((bit ^ flip) << (31 - k));
  }
  return out;
}
float unitOf(uint b) { return bitsToUnit(b); }
typedef double (*F)(double, double);
double disc(double x, double y) {
  double dx = x - 0.41, dy = y - 0.53;
  return dx * dx + dy * dy < 0.09 ? 1 : 0;
}
double edge(double x, double y) { return (0.7 * x + 0.3 * y + 0.11 * sin(5 * x)) > 0.43 ? 1 : 0; }
double gauss(double x, double y) { return exp(-8 * ((x - 0.45) * (x - 0.45) + (y - 0.6) * (y - 0.6))); }
double cosw(double x, double y) {  // lambert-like: direction eval on sphere
  return (x < 0.3 ? 0.2 : 1.0) * sqrt(y);
}
int main() {
  F fs[4] = {disc, edge, gauss, cosw};
  const char* names[4] = {"disc", "edge", "gauss", "step*sqrt"};
  int Ns[3] = {16, 64, 256};
  int trials = 20000;
  for (int fi = 0; fi < 4; fi++)
    for (int ni = 0; ni < 3; ni++) {
      int N = Ns[ni];
      double s1[4] = {0}, s2[4] = {0};
      std::mt19937 rng(123);
      for (int t = 0; t < trials; t++) {
        uint seed = hashU32(t * 7919u + 13u);
        uint s0 = hashU32(seed ^ 0x1b873593u), s1s = hashU32(seed ^ (1u + 0x1b873593u));
        double acc[4] = {0};
        for (int i = 0; i < N; i++) {
          // vkmc: shuffled index then LK scramble per component
          uint idx = shuffleIndex(i, seed);
          double x = unitOf(owenScramble(sobolBits(idx, 0), s0)), y = unitOf(owenScramble(sobolBits(idx, 1), s1s));
          acc[0] += fs[fi](x, y);
          // true Owen, unshuffled (first N points)
          double xt = unitOf(trueOwen(sobolBits(i, 0), s0)), yt = unitOf(trueOwen(sobolBits(i, 1), s1s));
          acc[1] += fs[fi](xt, yt);
          // independent
          std::uniform_real_distribution<double> U(0, 1);
          acc[2] += fs[fi](U(rng), U(rng));
          // LK unshuffled
          double xl = unitOf(owenScramble(sobolBits(i, 0), s0)), yl = unitOf(owenScramble(sobolBits(i, 1), s1s));
          acc[3] += fs[fi](xl, yl);
        }
        for (int k = 0; k < 4; k++) {
          double m = acc[k] / N;
          s1[k] += m;
          s2[k] += m * m;
        }
      }
      double v[4];
      for (int k = 0; k < 4; k++) {
        double m = s1[k] / trials;
        v[k] = s2[k] / trials - m * m;
      }
      printf("%-10s N=%4d  vkmc/indep %.4f  trueOwen/indep %.4f  LKunshuf/indep %.4f  vkmc/trueOwen %.3f\n", names[fi], N,
             v[0] / v[2], v[1] / v[2], v[3] / v[2], v[0] / v[1]);
    }
}
