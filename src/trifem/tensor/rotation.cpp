// SPDX-License-Identifier: MIT
#include "trifem/tensor/rotation.hpp"

#include <cmath>

namespace trifem::rotation {
namespace {

/// Below this angle the coefficients come from their series (the closed forms lose digits to
/// cancellation; the terms the series leave out are below 1e-17 relative here).
constexpr Real kSeriesBelow = 0.3;

/// The coefficients of R, T and H at angle θ:
///   s = sin θ/θ, a = (1 − cos θ)/θ², b = (θ − sin θ)/θ³, da = a′/θ, db = b′/θ.
struct Coefficients {
  Real s, a, b, da, db;
};

/// f(θ) = Σ_k (−θ²)^k/(2k + shift)! and f′(θ)/θ.
struct Series {
  Real value = 0.0, derivative = 0.0;
};

Series series(Real theta2, int shift) {
  Real inverse_factorial = 1.0; // 1/(2k + shift)!
  for (int i = 2; i <= shift; ++i)
    inverse_factorial /= i;
  Series f;
  Real power = 1.0, previous = 0.0; // (−θ²)^k and (−θ²)^(k−1)
  for (int k = 0; k < 8; ++k) {
    f.value += power * inverse_factorial;
    f.derivative -= 2.0 * k * previous * inverse_factorial; // 2k (−1)^k θ^(2k−2)/(2k + shift)!
    previous = power;
    power *= -theta2;
    inverse_factorial /= (2 * k + shift + 1) * (2 * k + shift + 2);
  }
  return f;
}

Coefficients coefficients(Real theta) {
  if (theta < kSeriesBelow) {
    const Real t2 = theta * theta;
    const Series a = series(t2, 2), b = series(t2, 3);
    return {series(t2, 1).value, a.value, b.value, a.derivative, b.derivative};
  }
  const Real s = std::sin(theta), c = std::cos(theta);
  const Real t2 = theta * theta, t3 = t2 * theta, t4 = t3 * theta;
  return {s / theta, (1.0 - c) / t2, (theta - s) / t3, (theta * s - 2.0 * (1.0 - c)) / t4,
          (3.0 * s - 2.0 * theta - theta * c) / (t4 * theta)};
}

} // namespace

Mat3 matrix(const Vec3& theta) {
  const Coefficients c = coefficients(theta.norm());
  const Mat3 S = skew(theta);
  return Mat3::Identity() + c.s * S + c.a * S * S;
}

Vec3 vector(const Mat3& R) {
  // the unit quaternion (w, v) of R, from its largest component (Shepperd)
  const Real trace = R.trace();
  Real w;
  Vec3 v;
  int largest = 0;
  R.diagonal().maxCoeff(&largest);
  if (trace >= R(largest, largest)) {
    w = 0.5 * std::sqrt(1.0 + trace);
    v = Vec3(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1)) / (4.0 * w);
  } else {
    const int i = largest, j = (i + 1) % 3, k = (i + 2) % 3;
    v[i] = 0.5 * std::sqrt(1.0 + R(i, i) - R(j, j) - R(k, k));
    w = (R(k, j) - R(j, k)) / (4.0 * v[i]);
    v[j] = (R(j, i) + R(i, j)) / (4.0 * v[i]);
    v[k] = (R(k, i) + R(i, k)) / (4.0 * v[i]);
  }
  if (w < 0.0) {
    w = -w;
    v = -v;
  }
  const Real n = v.norm();
  return n > 0.0 ? Vec3(2.0 * std::atan2(n, w) / n * v) : Vec3::Zero();
}

Mat3 tangent(const Vec3& theta) {
  const Coefficients c = coefficients(theta.norm());
  const Mat3 S = skew(theta);
  return Mat3::Identity() + c.a * S + c.b * S * S;
}

Mat3 tangent_derivative(const Vec3& theta, const Vec3& m) {
  // Tᵀm = m − a Θ×m + b (Θ(Θ·m) − θ²m), differentiated term by term
  const Coefficients c = coefficients(theta.norm());
  const Real tm = theta.dot(m), t2 = theta.squaredNorm();
  return c.a * skew(m) - c.da * theta.cross(m) * theta.transpose() +
         c.b * (tm * Mat3::Identity() + theta * m.transpose() - 2.0 * m * theta.transpose()) +
         c.db * (theta * tm - t2 * m) * theta.transpose();
}

} // namespace trifem::rotation
