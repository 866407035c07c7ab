#ifndef slidewave_engine_velocity_transfer_h
#define slidewave_engine_velocity_transfer_h

#include <array>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <slidewave/particles/property_layout.h>
#include <string>

namespace slidewave
{
  namespace engine
  {
    /**
     * How the points' velocities go to the grid and come back (TransferKernels).
     *
     * - `flip`: the points scatter m_p v_p and take back a blend of the nodal velocity
     *   (PIC) and of their own velocity plus its increment (FLIP), ParticleEngine's
     *   'FLIP fraction'.
     * - `apic`: the affine particle-in-cell transfer (Jiang, Schroeder, Selle, Teran and
     *   Stomakhin 2015). Each point carries, besides v_p, the affine matrix C_p (four
     *   properties, "affine_xx", "affine_xy", "affine_yx", "affine_yy", where "affine_xy"
     *   is dv_x/dy), scatters m_p N_I (v_p + C_p (x_I − x̄_p)) to node I, with the lever
     *   arms from x̄_p = Σ_J N_J x_J (x_p except where a GIMP or B-spline domain is cut
     *   by the grid's side), so that the affine part adds no momentum, and takes back the
     *   nodal velocity v_p = Σ_I N_I v_I (PIC) and C_p = Σ_I v_I ⊗ ∇N_I, the gradient of
     *   the new nodal field at the point. With bilinear (Q1) functions this is APIC's
     *   B_p D_p⁻¹ at the point where it is gathered; with GIMP and the B-splines the
     *   gradient stands in for it. Angular momentum is therefore not conserved to
     *   round-off (doc/mpm.md, "APIC"), but the local rotations and shears that PIC damps
     *   are kept, without FLIP's noise.
     */
    enum class VelocityTransfer
    {
      flip,
      apic
    };

    /** The names of the affine matrix's properties, xx, xy, yx, yy (C_ij = dv_i/dx_j), in
     *  the order they follow one another among a point's properties. */
    inline const std::array<std::string, 4> &
    affine_property_names()
    {
      static const std::array<std::string, 4> names{
        {"affine_xx", "affine_xy", "affine_yx", "affine_yy"}};
      return names;
    }

    /** What a checkpoint's signature says of @p transfer: nothing for the FLIP blend (the
     *  signatures of earlier checkpoints), "; velocity transfer apic" for APIC, whose
     *  points carry four more properties. */
    inline std::string
    signature(const VelocityTransfer transfer)
    {
      return transfer == VelocityTransfer::apic ? "; velocity transfer apic" : "";
    }

    /** With APIC, the index of "affine_xx" in @p layout (the other three follow it);
     *  otherwise invalid. */
    inline unsigned int
    affine_index(const particles::PropertyLayout &layout, const VelocityTransfer transfer)
    {
      if (transfer != VelocityTransfer::apic)
        return dealii::numbers::invalid_unsigned_int;
      const auto &names = affine_property_names();
      AssertThrow(layout.has(names[0]),
                  dealii::ExcMessage("APIC: the particle model's points carry no affine "
                                     "matrix (it must add affine_property_names())"));
      const unsigned int first = layout.index(names[0]);
      for (unsigned int k = 1; k < names.size(); ++k)
        AssertThrow(layout.has(names[k]) && layout.index(names[k]) == first + k,
                    dealii::ExcMessage("APIC: the affine matrix's properties must follow "
                                       "one another"));
      return first;
    }
  } // namespace engine
} // namespace slidewave

#endif
