#pragma once
// The monomial basis of degree-7 polynomials on the unit interval s in [0, 1], and the constant
// matrices of the minimum-snap problem on it (Richter, Bry and Roy 2013, Sec. 3: the cost matrix
// Q, the end-derivative map A, and the cost in end derivatives A^-T Q A^-1).
#include <Eigen/Core>

namespace cosim::polynomial_basis {

using Matrix8d = Eigen::Matrix<double, 8, 8>;
using Coefficients = Eigen::Matrix<double, 8, 3>;

// The r-th derivative with respect to s of sum_k c_k s^k, for each column of c.
Eigen::Vector3d evaluate(const Coefficients& c, int r, double s);

// Q_jk = int_0^1 (d^4 s^j / ds^4)(d^4 s^k / ds^4) ds: int |q''''|^2 ds = c^T Q c.
const Matrix8d& unitSnapCostMatrix();

// A maps the coefficients c to the end derivatives [q(0), q'(0), q''(0), q'''(0), q(1), q'(1),
// q''(1), q'''(1)] = A c. With 8 coefficients A is square and invertible: the 8 end
// derivatives determine the piece.
const Matrix8d& unitEndDerivativeMatrix();
const Matrix8d& unitEndDerivativeMatrixInverse();

// H = A^-T Q A^-1: the snap cost of a unit-interval piece as a quadratic form in its end
// derivatives, int |q''''|^2 ds = d^T H d.
const Matrix8d& unitEndDerivativeCost();

}  // namespace cosim::polynomial_basis
