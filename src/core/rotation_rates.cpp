#include "core/rotation_rates.h"

#include <Eigen/Geometry>

namespace cablefilm {

RotationRates RotationInTime(const Vec& angles, const Vec& rates, const Vec& rates2) {
  // Each factor turns about one axis e by one angle a(t): A = exp(a K), K = [e]x, so
  // A' = a' K A and A'' = (a'' K + a'^2 K K) A. The product's derivatives by Leibniz:
  // (Z Y X)' = Z'YX + ZY'X + ZYX', (ZYX)'' = Z''YX + ZY''X + ZYX'' + 2 (Z'Y'X + Z'YX' + ZY'X').
  Mat A[3], dA[3], d2A[3];  // x, y, z factors
  for (int k = 0; k < 3; ++k) {
    const Vec e = Vec::Unit(k);
    Mat K;
    K << 0, -e[2], e[1], e[2], 0, -e[0], -e[1], e[0], 0;
    A[k] = Eigen::AngleAxisd(angles[k], e).toRotationMatrix();
    dA[k] = rates[k] * K * A[k];
    d2A[k] = (rates2[k] * K + rates[k] * rates[k] * K * K) * A[k];
  }
  const Mat &X = A[0], &Y = A[1], &Z = A[2];
  RotationRates out;
  out.R = Z * Y * X;
  out.dR = dA[2] * Y * X + Z * dA[1] * X + Z * Y * dA[0];
  out.d2R = d2A[2] * Y * X + Z * d2A[1] * X + Z * Y * d2A[0] +
            2.0 * (dA[2] * dA[1] * X + dA[2] * Y * dA[0] + Z * dA[1] * dA[0]);
  return out;
}

}  // namespace cablefilm
