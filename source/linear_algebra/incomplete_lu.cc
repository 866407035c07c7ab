#include <Ifpack.h>
#include <Ifpack_Preconditioner.h>
#include <Teuchos_ParameterList.hpp>
#include <slidewave/linear_algebra/incomplete_lu.h>
#include <stdexcept>
#include <string>

namespace slidewave
{
  namespace linear_algebra
  {
    IncompleteLU::IncompleteLU(const unsigned int fill)
      : fill(fill)
    {
    }



    void
    IncompleteLU::factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix)
    {
      const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
      const auto              check  = [](const int code, const char *what) {
        if (code != 0)
          throw std::runtime_error(std::string("Ifpack's incomplete LU failed in ") + what
                                   + " (error code " + std::to_string(code) + ")");
      };
      if (ifpack == nullptr || factored != &epetra)
        {
          // Symbolic: the fill pattern of ILU(fill) on each rank's rows (Ifpack's
          // "ILU", additive Schwarz without overlap, absolute threshold 0 and relative
          // threshold 1: the matrix's own values, as deal.II's PreconditionILU).
          Ifpack factory;
          ifpack = factory.Create("ILU", const_cast<Epetra_CrsMatrix *>(&epetra), 0);
          if (ifpack == nullptr)
            throw std::runtime_error("Ifpack could not create an incomplete LU");
          preconditioner = Teuchos::rcp(ifpack);
          Teuchos::ParameterList list;
          list.set("fact: level-of-fill", static_cast<int>(fill));
          list.set("fact: absolute threshold", 0.);
          list.set("fact: relative threshold", 1.);
          list.set("schwarz: combine mode", "Add");
          check(ifpack->SetParameters(list), "SetParameters");
          check(ifpack->Initialize(), "Initialize");
          factored = &epetra;
        }
      check(ifpack->Compute(), "Compute"); // numeric: the current values
    }
  } // namespace linear_algebra
} // namespace slidewave
