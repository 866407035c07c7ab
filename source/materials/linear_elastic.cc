#include <slidewave/materials/linear_elastic.h>

namespace slidewave
{
  namespace materials
  {
    LinearElastic::LinearElastic(const double youngs_modulus, const double poisson_ratio)
      : bulk(youngs_modulus / (3. * (1. - 2. * poisson_ratio)))
      , shear(youngs_modulus / (2. * (1. + poisson_ratio)))
    {
    }



    dealii::SymmetricTensor<2, 3>
    LinearElastic::stress_increment(const dealii::SymmetricTensor<2, 3> &strain_increment) const
    {
      return lame_lambda() * dealii::trace(strain_increment) * dealii::unit_symmetric_tensor<3>()
             + 2. * shear * strain_increment;
    }



    dealii::SymmetricTensor<2, 3>
    LinearElastic::strain_increment(const dealii::SymmetricTensor<2, 3> &stress_increment) const
    {
      return dealii::trace(stress_increment) / (9. * bulk) * dealii::unit_symmetric_tensor<3>()
             + dealii::deviator(stress_increment) / (2. * shear);
    }



    double
    LinearElastic::bulk_modulus() const
    {
      return bulk;
    }



    double
    LinearElastic::shear_modulus() const
    {
      return shear;
    }



    double
    LinearElastic::lame_lambda() const
    {
      return bulk - 2. * shear / 3.;
    }



    double
    LinearElastic::p_wave_modulus() const
    {
      return bulk + 4. * shear / 3.;
    }
  } // namespace materials
} // namespace slidewave
