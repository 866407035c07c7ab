#ifndef slidewave_linear_algebra_incomplete_lu_h
#define slidewave_linear_algebra_incomplete_lu_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

class Ifpack_Preconditioner;

namespace slidewave
{
  namespace linear_algebra
  {
    /**
     * ILU(k) of a Trilinos matrix (Ifpack, additive Schwarz without overlap between ranks,
     * as deal.II's PreconditionILU) that keeps its symbolic factorization: the fill pattern
     * depends on the matrix's sparsity only, so a matrix whose values change every step
     * (a time-dependent flow) is factorized numerically again without rebuilding it. The
     * factors equal those of a fresh PreconditionILU with the same fill, bit for bit.
     *
     * Bound to one matrix object and its sparsity: after the matrix is reinitialized (a
     * grid change), make a new one.
     */
    class IncompleteLU : public dealii::TrilinosWrappers::PreconditionBase
    {
    public:
      /** ILU with @p fill levels of fill (0: the matrix's own pattern). */
      explicit IncompleteLU(unsigned int fill);

      /** The factors of @p matrix's current values; the symbolic part only the first
       *  time (@p matrix must be the same object, with the same sparsity, every call). */
      void
      factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    private:
      unsigned int            fill;
      Ifpack_Preconditioner  *ifpack   = nullptr; // owned by PreconditionBase::preconditioner
      const Epetra_CrsMatrix *factored = nullptr;
    };
  } // namespace linear_algebra
} // namespace slidewave

#endif
