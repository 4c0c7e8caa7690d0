// Student's t for tests whose standard error is itself estimated from few degrees of freedom: one pixel of a
// QMC render has R replicate means (R - 1 dof: 1 by default, 3 with 4 replicates), so a bound of 5 sigma taken
// from the normal would pass an unbiased pixel only 98.5% of the time at 3 dof (87% at 1) instead of 99.99994%.
#pragma once

namespace vkmc {

// I_x(a, b), the regularized incomplete beta function (continued fraction, Lentz's method).
double regularizedIncompleteBeta(double a, double b, double x);
// P(|T| > t) for Student's t with `dof` degrees of freedom (dof = infinity: the normal's).
double studentTwoSidedTail(double t, double dof);
// The bound on |t| with the two-sided false-positive rate of |z| > k for a normal z: what "k sigma" means when
// sigma has `dof` degrees of freedom (5 sigma: 157 at 3 dof, 11.2 at 10, 5.57 at 63; exactly k from 1e7 dof on,
// infinity included).
double studentBoundForSigmas(double k, double dof);
// Welch-Satterthwaite: the degrees of freedom of va + vb, two independent variance estimates with dofA and dofB.
double welchDof(double va, double dofA, double vb, double dofB);

}  // namespace vkmc
