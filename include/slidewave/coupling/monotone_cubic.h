#ifndef slidewave_coupling_monotone_cubic_h
#define slidewave_coupling_monotone_cubic_h

#include <vector>

namespace slidewave
{
  namespace coupling
  {
    /**
     * Piecewise cubic Hermite interpolation that keeps the monotonicity of the data
     * (Fritsch and Carlson 1980, with the harmonic-mean slopes of Fritsch and Butland
     * 1984): between two samples the interpolant stays within their values, so a steep
     * soil face or a corner gives no spurious bump or dip in the bed. C^1, exact for
     * linear data, constant beyond the first and last samples.
     */
    class MonotoneCubic
    {
    public:
      /** Sets the samples (x_k strictly increasing); storage is reused. */
      void
      reinit(const std::vector<double> &x, const std::vector<double> &y);

      double
      value(double x) const;

    private:
      std::vector<double> xs, ys, slopes;
    };
  } // namespace coupling
} // namespace slidewave

#endif
