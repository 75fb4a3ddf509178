#pragma once
// Four doubles in one vector register (GCC's and Clang's vector extension), for the few small
// dense loops of a time step that sum across an inner index: GCC's vectoriser turns the scalar
// form of such a loop into products and separate adds. Multiply-adds are explicit, fused where
// the machine has FMA (x86-64-v3, as Eigen's packets are there), so the bits do not depend on
// the optimisation level or contraction setting of the file that includes this.
#include <cmath>
#include <cstring>
#ifdef __FMA__
#include <immintrin.h>
#endif

namespace pound {

using Packet4 = double __attribute__((vector_size(4 * sizeof(double))));

inline Packet4 load_packet(const double* from) {
  Packet4 packet;
  std::memcpy(&packet, from, sizeof packet);
  return packet;
}

inline void store_packet(const Packet4& packet, double* to) {
  std::memcpy(to, &packet, sizeof packet);
}

// c + a b, rounded once where the machine fuses multiply-adds.
inline double multiply_add(double a, double b, double c) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return c + a * b;
#endif
}

inline Packet4 multiply_add(Packet4 a, Packet4 b, Packet4 c) {
#ifdef __FMA__
  return _mm256_fmadd_pd(a, b, c);
#else
  return c + a * b;
#endif
}

inline Packet4 broadcast(double value) { return Packet4{value, value, value, value}; }

// y = A x for a column-major Rows x Cols matrix A: each row summed from 0 in column order, four
// rows to a packet, the rest by multiply_add; without the set-up of Eigen's general
// matrix-vector product, which costs more than a 12 x 12 product. (Eigen groups the columns of
// a dense matrix otherwise, so the bits may differ from its product; on the beams' matrices,
// a few terms a row, every bundled model gave the same bits.)
template <int Rows, int Cols>
void multiply_by_columns(const double* a, const double* x, double* y) {
  constexpr int kPacked = Rows / 4 * 4;
  for (int i = 0; i < kPacked; i += 4) {
    Packet4 sums{};
    for (int j = 0; j < Cols; ++j)
      sums = multiply_add(load_packet(a + j * Rows + i), broadcast(x[j]), sums);
    store_packet(sums, y + i);
  }
  for (int i = kPacked; i < Rows; ++i) {
    double sum = 0.0;
    for (int j = 0; j < Cols; ++j) sum = multiply_add(a[j * Rows + i], x[j], sum);
    y[i] = sum;
  }
}

}  // namespace pound
