#include "planning/trajectory/polynomial_basis.h"

#include <Eigen/LU>

namespace cosim::polynomial_basis {
namespace {

// k! / (k - r)!: the factor d^r/ds^r brings to s^k (0 if r > k).
double fallingFactorial(int k, int r) {
  if (r > k) return 0.0;
  double f = 1.0;
  for (int i = 0; i < r; ++i) f *= k - i;
  return f;
}

Matrix8d makeSnapCost() {
  Matrix8d Q = Matrix8d::Zero();
  for (int j = 4; j < 8; ++j)
    for (int k = 4; k < 8; ++k)
      Q(j, k) = fallingFactorial(j, 4) * fallingFactorial(k, 4) / (j + k - 7);
  return Q;
}

Matrix8d makeEndDerivatives() {
  Matrix8d A = Matrix8d::Zero();
  for (int r = 0; r < 4; ++r) {
    A(r, r) = fallingFactorial(r, r);                                  // at s = 0
    for (int k = r; k < 8; ++k) A(4 + r, k) = fallingFactorial(k, r);  // at s = 1
  }
  return A;
}

}  // namespace

Eigen::Vector3d evaluate(const Coefficients& c, int r, double s) {
  // Horner's rule on the r-th derivative's coefficients.
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (int k = 7; k >= r; --k) value = value * s + fallingFactorial(k, r) * c.row(k).transpose();
  return value;
}

const Matrix8d& unitSnapCostMatrix() {
  static const Matrix8d Q = makeSnapCost();
  return Q;
}

const Matrix8d& unitEndDerivativeMatrix() {
  static const Matrix8d A = makeEndDerivatives();
  return A;
}

const Matrix8d& unitEndDerivativeMatrixInverse() {
  static const Matrix8d A_inv = unitEndDerivativeMatrix().inverse();
  return A_inv;
}

const Matrix8d& unitEndDerivativeCost() {
  static const Matrix8d H = unitEndDerivativeMatrixInverse().transpose() * unitSnapCostMatrix() *
                            unitEndDerivativeMatrixInverse();
  return H;
}

}  // namespace cosim::polynomial_basis
