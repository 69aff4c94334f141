// What the vector unit gives the time step's per-point arithmetic alone
// (doc/performance.md, "What the vector unit gives"): the signal speed
//   s_p = sqrt(K / rho_p) + |v_p| + 4 nu / (rho_p h_p),  rho_p = m_p / V_p,
// and its maximum over 102 400 points (the 2D benchmark's count), three
// ways in one run: scalar (vectorisation switched off), SSE2 (the
// compiler's vectorisation at the build's x86-64 baseline: two doubles per
// division and square root) and, where the processor has it, AVX2 (four).
// The arithmetic is a few divisions and square roots per point, which
// bound it; all three give the same maximum (asserted: the operations are
// IEEE-exact in every width). Prints one line per variant, the best of
// 200 repetitions:
//   SIMD <variant> ms=<ms> ns_per_point=<ns> speedup=<vs scalar>
// Not a test of fsgmpm's code: a measure of what restructuring a stage's
// per-point loops for the vector unit can give at most.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{
  struct Points
  {
    std::vector<double> m, V, vx, vy, h, s;
  };

  constexpr double K = 2.5e6, viscous = 4 * 8.9e-4;

  // The same loop three times, compiled with different options.
#define SIGNAL_SPEED_FUNCTION(name, ...)                                     \
  __attribute__((__VA_ARGS__, noinline)) double name(const double *m,        \
                                                     const double *V,        \
                                                     const double *vx,       \
                                                     const double *vy,       \
                                                     const double *h,        \
                                                     double       *s,        \
                                                     std::size_t   n)        \
  {                                                                          \
    for (std::size_t p = 0; p < n; ++p)                                      \
      {                                                                      \
        const double rho = m[p] / V[p];                                      \
        s[p] = std::sqrt(K / rho) + std::sqrt(vx[p] * vx[p] + vy[p] * vy[p]) \
               + viscous / (rho * h[p]);                                     \
      }                                                                      \
    double largest = 0;                                                      \
    for (std::size_t p = 0; p < n; ++p)                                      \
      largest = std::max(largest, s[p]);                                     \
    return largest;                                                          \
  }

  SIGNAL_SPEED_FUNCTION(scalar, optimize("no-tree-vectorize"))
  SIGNAL_SPEED_FUNCTION(sse2, optimize("tree-vectorize"))
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#  define FSGMPM_HAVE_AVX2_VARIANT 1
  SIGNAL_SPEED_FUNCTION(avx2, target("avx2"), optimize("tree-vectorize"))
#endif

  template <typename Function>
  std::pair<double, double>
  best_of(Points &x, const Function &f)
  {
    double best = 1e30, largest = 0;
    for (unsigned int repetition = 0; repetition < 200; ++repetition)
      {
        const auto t0 = std::chrono::steady_clock::now();
        largest       = f(x.m.data(),
                    x.V.data(),
                    x.vx.data(),
                    x.vy.data(),
                    x.h.data(),
                    x.s.data(),
                    x.m.size());
        best          = std::min(best,
                        std::chrono::duration<double>(
                          std::chrono::steady_clock::now() - t0)
                          .count());
      }
    return {best, largest};
  }
} // namespace

int
main()
{
  const std::size_t n = 102400;
  Points            x;
  for (auto *v : {&x.m, &x.V, &x.vx, &x.vy, &x.h, &x.s})
    v->resize(n);
  std::mt19937                           rng(1);
  std::uniform_real_distribution<double> u(0.9, 1.1), v(-2, 2);
  for (std::size_t p = 0; p < n; ++p)
    {
      x.m[p]  = 1e-3 * u(rng);
      x.V[p]  = 1e-6 * u(rng);
      x.vx[p] = v(rng);
      x.vy[p] = v(rng);
      x.h[p]  = 4e-3 * u(rng);
    }
  const auto report = [n](const char                      *variant,
                          const std::pair<double, double> &t,
                          const std::pair<double, double> &reference) {
    if (t.second != reference.second)
      {
        std::fprintf(stderr,
                     "%s: maximum %.17g differs from the scalar %.17g\n",
                     variant,
                     t.second,
                     reference.second);
        std::exit(1);
      }
    std::printf("SIMD %s ms=%.3f ns_per_point=%.2f speedup=%.2f\n",
                variant,
                1e3 * t.first,
                1e9 * t.first / n,
                reference.first / t.first);
  };
  const auto reference = best_of(x, scalar);
  report("scalar", reference, reference);
  report("sse2", best_of(x, sse2), reference);
#ifdef FSGMPM_HAVE_AVX2_VARIANT
  if (__builtin_cpu_supports("avx2"))
    report("avx2", best_of(x, avx2), reference);
  else
    std::printf("SIMD avx2 not supported by this processor\n");
#endif
  return 0;
}
