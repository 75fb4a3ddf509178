#pragma once
// Four doubles in one vector register (GCC's and Clang's vector extension), for the few small
// dense loops of a time step whose sums must round exactly as Eigen's own vector loops round
// them: GCC's vectoriser turns the scalar form of a loop that sums across an inner index into
// products and separate adds, other bits than Eigen's fused multiply-adds. With FMA
// (x86-64-v3), -ffp-contract fuses `sums += a * b` on these as it does inside Eigen's packets;
// multiply_add does the same for a scalar left at a loop's end.
#include <cmath>
#include <cstring>

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

// c + a b, rounded once where the machine fuses multiply-adds (as the packets' sums are).
inline double multiply_add(double a, double b, double c) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return c + a * b;
#endif
}

}  // namespace pound
