// BLAS from two threads at once (numerics/blas_threads.cpp): each call's result is the one the
// same call gives alone, bit for bit. Without the lock around OpenBLAS's buffers, Debian's
// serial OpenBLAS gave 20–30 wrong results in these 40,000 calls.

#include "numerics/blas_threads.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

extern "C" void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
                       const double* a, const int* lda, const double* beta, double* c, const int* ldc);

namespace hydrodda::numerics {
namespace {

struct Product {  // C = A Aᵀ, lower triangle, A n × k with leading dimension lda
  int n, k, lda, ldc;
  std::vector<double> a, alone;
};

std::vector<double> lower_product(const Product& p) {
  static constexpr double one = 1.0, zero = 0.0;
  std::vector<double> c(static_cast<std::size_t>(p.ldc) * p.n, 0.0);
  dsyrk_("L", "N", &p.n, &p.k, &one, p.a.data(), &p.lda, &zero, c.data(), &p.ldc);
  return c;
}

TEST(BlasThreads, TheProgramsBuffersAreGuarded) { EXPECT_TRUE(blas_is_thread_safe()); }

TEST(BlasThreads, TwoThreadsGetWhatOneGets) {
  if (omp_get_max_threads() < 2) GTEST_SKIP() << "one thread only (OMP_NUM_THREADS)";
  std::mt19937 random(7);
  std::uniform_int_distribution<int> size(1, 120);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Product> products(2000);
  for (Product& p : products) {
    p.n = size(random);
    p.k = size(random);
    p.lda = p.n + size(random);
    p.ldc = p.n + size(random);
    p.a.resize(static_cast<std::size_t>(p.lda) * p.k);
    for (double& x : p.a) x = value(random);
    p.alone = lower_product(p);
  }
  int wrong = 0;
  for (int round = 0; round < 20; ++round) {
#pragma omp parallel num_threads(2) reduction(+ : wrong)
    for (std::size_t i = omp_get_thread_num(); i < products.size(); i += 2) {
      const std::vector<double> c = lower_product(products[i]);
      if (std::memcmp(c.data(), products[i].alone.data(), c.size() * sizeof(double)) != 0) ++wrong;
    }
  }
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace hydrodda::numerics
