// declare_run_parameters(): every module declares the entries it reads.
#include <impm/coupling/couplings.h>
#include <impm/io/shared_libraries.h>
#include <impm/postprocess/postprocessor.h>
#include <impm/simulator/material_test.h>
#include <impm/simulator/run.h>
#include <impm/simulator/strength_reduction.h>

namespace impm
{
  void
  declare_run_parameters(dealii::ParameterHandler &prm)
  {
    SharedLibraries::declare_parameters(prm);
    Parameters::declare_all(prm);
    Parameters::Solver::declare_parameters(prm);
    Parameters::Output::declare_parameters(prm);
    Parameters::Testing::declare_parameters(prm);
    Parameters::Checkpoint::declare_parameters(prm);
    Parameters::Time::declare_parameters(prm);
    Couplings<2>::declare_parameters(prm);
    PostprocessorManager<2>::declare_parameters(prm);
    MaterialTest::Parameters::declare_parameters(prm);
    Parameters::StrengthReduction::declare_parameters(prm);
  }
} // namespace impm
