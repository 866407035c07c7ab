#include <cmath>
#include <deal.II/base/exceptions.h>
#include <limits>
#include <slidewave/soil/finite_strain_points.h>
#include <slidewave/soil/particle_properties.h>

namespace slidewave
{
  namespace soil
  {
    namespace
    {
      /** b^e's components in the property array, from its first. */
      constexpr unsigned int xx = 0, yy = 1, xy = 2, zz = 3;
    } // namespace



    const std::array<std::string, 4> &
    FiniteStrainPoints::property_names()
    {
      static const std::array<std::string, 4> names{{"elastic_left_cauchy_green_xx",
                                                     "elastic_left_cauchy_green_yy",
                                                     "elastic_left_cauchy_green_xy",
                                                     "elastic_left_cauchy_green_zz"}};
      return names;
    }



    bool
    FiniteStrainPoints::needed(const std::vector<materials::MaterialParameters> &materials)
    {
      for (const auto &material : materials)
        if (material.model == materials::MaterialModel::hencky_drucker_prager)
          return true;
      return false;
    }



    FiniteStrainPoints::FiniteStrainPoints(
      const std::vector<materials::MaterialParameters> &materials,
      const unsigned int                                first_index)
      : first(first_index)
    {
      for (const auto &material : materials)
        {
          models.emplace_back();
          if (material.model == materials::MaterialModel::hencky_drucker_prager)
            models.back().emplace(material.youngs_modulus,
                                  material.poisson_ratio,
                                  material.friction_angle,
                                  material.cohesion,
                                  material.dilatancy_angle);
        }
    }



    void
    FiniteStrainPoints::initialize(std::vector<double> &properties) const
    {
      properties[first + xx] = 1.;
      properties[first + yy] = 1.;
      properties[first + xy] = 0.;
      properties[first + zz] = 1.;
    }



    dealii::Tensor<2, 2>
    FiniteStrainPoints::exponential(const dealii::Tensor<2, 2> &A)
    {
      // A = s I + B with B trace free, B^2 = d I (d = -det B): exp(A) = e^s (c I + h B)
      // with c = cosh(sqrt d), h = sinh(sqrt d) / sqrt d (cos and sin for d < 0). For
      // small |d| (every ordinary step) the series, to below round-off.
      const double         s = 0.5 * (A[0][0] + A[1][1]);
      dealii::Tensor<2, 2> B = A;
      B[0][0] -= s;
      B[1][1] -= s;
      const double d = B[0][0] * B[0][0] + B[0][1] * B[1][0];
      double       c, h;
      if (std::abs(d) < 1e-4)
        {
          c = 1. + d * (1. / 2. + d * (1. / 24. + d * (1. / 720. + d / 40320.)));
          h = 1. + d * (1. / 6. + d * (1. / 120. + d * (1. / 5040. + d / 362880.)));
        }
      else if (d > 0.)
        {
          const double r = std::sqrt(d);
          c              = std::cosh(r);
          h              = std::sinh(r) / r;
        }
      else
        {
          const double r = std::sqrt(-d);
          c              = std::cos(r);
          h              = std::sin(r) / r;
        }
      const double         scale = std::exp(s);
      dealii::Tensor<2, 2> result;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          result[i][j] = scale * ((i == j ? c : 0.) + h * B[i][j]);
      return result;
    }



    void
    FiniteStrainPoints::update(dealii::ArrayView<double>   p,
                               const dealii::Tensor<2, 2> &L,
                               const double                dt,
                               const double                volumetric_correction,
                               const double                alpha_psi) const
    {
      const auto &model = *models[static_cast<unsigned int>(p[property::material_id])];

      // f = exp(L dt), its volume change replaced by the cell's mean with B-bar (F-bar):
      // exp(c/2) scales the plane's two directions, so det f-bar = e^c det f.
      const dealii::Tensor<2, 2> f_plane = exponential(dt * L);
      const double               bar     = std::exp(0.5 * volumetric_correction);
      dealii::Tensor<2, 3>       f;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          f[i][j] = bar * f_plane[i][j];
      f[2][2]                   = 1.;
      const double volume_ratio = f[0][0] * f[1][1] - f[0][1] * f[1][0];
      p[property::volume] *= volume_ratio;
      const double J = p[property::volume] / p[property::initial_volume];

      dealii::SymmetricTensor<2, 3> be;
      be[0][0] = p[first + xx];
      be[1][1] = p[first + yy];
      be[0][1] = p[first + xy];
      be[2][2] = p[first + zz];

      // A run that has already failed (non-finite velocities, an overflowing step) makes
      // the model throw (b^e_trial not positive definite, det f <= 0), on this rank alone,
      // while the other ranks would wait in the next collective. The point is marked
      // non-finite instead, and the guards stop the run on every rank with its
      // description, as for the small-strain models.
      double                plastic = p[property::equivalent_plastic_strain];
      materials::HenckyStep step;
      try
        {
          step = std::isnan(alpha_psi) ? model.update(be, f, J, plastic) :
                                         model.update(be, f, J, plastic, alpha_psi);
        }
      catch (const dealii::ExceptionBase &)
        {
          const double nan = std::numeric_limits<double>::quiet_NaN();
          for (const unsigned int c :
               {property::stress_xx, property::stress_yy, property::stress_xy, property::stress_zz})
            p[c] = nan;
          for (unsigned int c = 0; c < 4; ++c)
            p[first + c] = nan;
          return;
        }

      p[first + xx]                          = be[0][0];
      p[first + yy]                          = be[1][1];
      p[first + xy]                          = be[0][1];
      p[first + zz]                          = be[2][2];
      p[property::stress_xx]                 = step.cauchy_stress[0][0];
      p[property::stress_yy]                 = step.cauchy_stress[1][1];
      p[property::stress_xy]                 = step.cauchy_stress[0][1];
      p[property::stress_zz]                 = step.cauchy_stress[2][2];
      p[property::equivalent_plastic_strain] = plastic;
    }



    void
    FiniteStrainPoints::set_from_stress(dealii::ArrayView<double> p) const
    {
      const auto &model = models[static_cast<unsigned int>(p[property::material_id])];
      if (!model)
        return;
      const double                  J = p[property::volume] / p[property::initial_volume];
      dealii::SymmetricTensor<2, 3> tau;
      tau[0][0]     = J * p[property::stress_xx];
      tau[1][1]     = J * p[property::stress_yy];
      tau[0][1]     = J * p[property::stress_xy];
      tau[2][2]     = J * p[property::stress_zz];
      const auto be = model->elastic_left_cauchy_green(tau);
      p[first + xx] = be[0][0];
      p[first + yy] = be[1][1];
      p[first + xy] = be[0][1];
      p[first + zz] = be[2][2];
    }
  } // namespace soil
} // namespace slidewave
