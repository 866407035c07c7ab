#include <algorithm>
#include <cmath>
#include <slidewave/soil/hencky_exact_solution.h>

namespace slidewave
{
  namespace soil
  {
    namespace
    {
      /** exp(A) by a Taylor series of A / 2^m (norm below 1/2), squared m times. */
      dealii::Tensor<2, 2>
      exponential_by_series(const dealii::Tensor<2, 2> &A)
      {
        unsigned int m = 0;
        while (A.norm() / std::pow(2., m) > 0.5)
          ++m;
        const dealii::Tensor<2, 2> a = A / std::pow(2., m);
        dealii::Tensor<2, 2>       sum, term;
        sum[0][0] = sum[1][1] = term[0][0] = term[1][1] = 1.;
        for (unsigned int k = 1; k < 30; ++k)
          {
            term = term * a / static_cast<double>(k);
            sum += term;
          }
        for (unsigned int i = 0; i < m; ++i)
          sum = sum * sum;
        return sum;
      }

      double
      coefficient(const double angle_degrees)
      {
        const double t = std::tan(angle_degrees * M_PI / 180.);
        return t / std::sqrt(9. + 12. * t * t);
      }
    } // namespace



    HenckyExactState
    hencky_homogeneous_state(const materials::MaterialParameters &material,
                             const dealii::Tensor<2, 2>          &L,
                             const double                         t)
    {
      const double E = material.youngs_modulus, nu = material.poisson_ratio;
      const double K = E / (3. * (1. - 2. * nu));
      const double G = E / (2. * (1. + nu));

      const dealii::Tensor<2, 2> F = exponential_by_series(t * L);
      const dealii::Tensor<2, 2> b = F * dealii::transpose(F);
      HenckyExactState           state;
      state.jacobian = F[0][0] * F[1][1] - F[0][1] * F[1][0];

      // Principal values of the 2 x 2 b and the angle of its first axis; the third is z.
      const double mean   = 0.5 * (b[0][0] + b[1][1]);
      const double radius = std::hypot(0.5 * (b[0][0] - b[1][1]), b[0][1]);
      const double angle  = 0.5 * std::atan2(b[0][1], 0.5 * (b[0][0] - b[1][1]));
      const double eps[3] = {0.5 * std::log(mean + radius), 0.5 * std::log(mean - radius), 0.};

      // Hencky stress, then the return from the stress-free state in one step.
      const double volumetric = eps[0] + eps[1] + eps[2];
      double       p          = K * volumetric;
      double       s[3];
      for (unsigned int a = 0; a < 3; ++a)
        s[a] = 2. * G * (eps[a] - volumetric / 3.);
      const double q_trial   = std::sqrt(0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
      const double alpha_phi = coefficient(material.friction_angle);
      const double alpha_psi = coefficient(material.dilatancy_angle);
      const double t_phi     = std::tan(material.friction_angle * M_PI / 180.);
      const double k_c       = 3. * material.cohesion / std::sqrt(9. + 12. * t_phi * t_phi);
      const double f         = 3. * alpha_phi * p + q_trial - k_c;
      double       q         = q_trial;
      if (f > 0.)
        {
          state.plastic       = true;
          const double dgamma = f / (G + 9. * K * alpha_phi * alpha_psi);
          q                   = q_trial - G * dgamma;
          p                   = p - 3. * K * alpha_psi * dgamma;
          if (q < 0. && alpha_phi > 0.)
            {
              p = k_c / (3. * alpha_phi);
              q = 0.;
            }
          q = std::max(q, 0.);
        }
      const double scale = q_trial > 0. ? q / q_trial : 0.;
      double       tau[3];
      for (unsigned int a = 0; a < 3; ++a)
        tau[a] = p + scale * s[a];

      // Back to x, y: the first axis at 'angle', the second normal to it.
      const double c = std::cos(angle), n = std::sin(angle);
      const double J            = state.jacobian;
      state.cauchy_stress[0][0] = (tau[0] * c * c + tau[1] * n * n) / J;
      state.cauchy_stress[1][1] = (tau[0] * n * n + tau[1] * c * c) / J;
      state.cauchy_stress[0][1] = (tau[0] - tau[1]) * c * n / J;
      state.cauchy_stress[2][2] = tau[2] / J;
      return state;
    }
  } // namespace soil
} // namespace slidewave
