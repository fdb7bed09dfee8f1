// Central differences for gradient checks: tests compare an analytic
// gradient with these, one parameter at a time.
#pragma once

// (loss(x + eps) - loss(x - eps)) / (2 eps), where loss() reads the parameter
// x in place; x is restored before returning.
template <class Loss>
double central_difference(float& x, float eps, Loss&& loss) {
  const float keep = x;
  x = keep + eps;
  const double up = loss();
  x = keep - eps;
  const double down = loss();
  x = keep;
  return (up - down) / (2.0 * eps);
}
