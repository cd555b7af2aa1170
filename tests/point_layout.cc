// PointLayout: the optional properties laid out from what the bodies'
// materials and the couplings declare (issue 30). Expected by hand: in 2D
// the fixed properties are X (2), F (9), b^e (6), tau (6), V0, m and the
// current and initial GIMP half-lengths (2 + 2): 29 entries, so the body
// index is property 29 and the material block starts at 30. The bodies'
// materials share that block (a point has one body): its length is the
// longest material's state (1 + 6 = 7), not the sum (8), so the couplings'
// fields start at 37 and the points have 37 + 8 + 2 = 47 properties.
#include <impm/core/point_properties.h>
#include <impm/mechanics/material.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "tests.h"

using namespace impm;

namespace
{
  std::string
  first(const unsigned int index)
  {
    return index == PointLayout::absent ? "-" : std::to_string(index);
  }

  void
  print(const PointLayout &layout)
  {
    std::cout << "properties " << layout.n_properties() << ", body index "
              << first(layout.body_index()) << ", material block from "
              << layout.material_state_first() << std::endl;
    for (const auto &field : layout.written_fields())
      {
        std::cout << "  written " << field.name << " (" << field.n_components
                  << "): first by body";
        for (const unsigned int index : field.first_by_body)
          std::cout << ' ' << first(index);
        std::cout << std::endl;
      }
    std::cout << "  description: " << layout.description() << std::endl;
  }

  void
  expect_logic_error(const std::string              &what,
                     const std::vector<PointFields> &materials,
                     const PointFields              &couplings)
  {
    PointLayout layout;
    try
      {
        layout.initialize(29, materials, couplings);
        std::cout << what << ": accepted (WRONG)" << std::endl;
      }
    catch (const std::logic_error &error)
      {
        std::cout << what << ": " << error.what() << std::endl;
      }
  }
} // namespace

int
main()
{
  const HenckyVonMises elastic(1e6,
                               0.3,
                               std::numeric_limits<double>::infinity());
  const HenckyVonMises plastic(1e6, 0.3, 2e4);
  // A model with more state, as a critical-state model would declare it.
  const PointFields critical_state = {{"preconsolidation_pressure", 1, true},
                                      {"back_stress", 6, true}};
  const PointFields couplings      = {{"contact_friction_traction", 8, false},
                                      {"spring_displacement", 2, true}};

  std::cout << "elastic declares " << elastic.state_fields().size()
            << " fields, von Mises " << plastic.state_fields().size() << " ("
            << plastic.state_fields()[0].name << ")" << std::endl;

  PointLayout layout;
  layout.initialize(PointProperties<2>::n_fixed_properties,
                    {elastic.state_fields(),
                     plastic.state_fields(),
                     critical_state},
                    couplings);
  print(layout);
  std::cout << "  state entries by body " << layout.n_material_state(0) << ' '
            << layout.n_material_state(1) << ' ' << layout.n_material_state(2)
            << "; friction from "
            << first(layout.coupling_field("contact_friction_traction"))
            << ", springs from "
            << first(layout.coupling_field("spring_displacement"))
            << ", none from " << first(layout.coupling_field("none"))
            << std::endl;

  // One body: no body index, the material block right after the fixed
  // properties.
  PointLayout single;
  single.initialize(PointProperties<3>::n_fixed_properties,
                    {plastic.state_fields()},
                    {});
  print(single);

  expect_logic_error("one name, two sizes",
                     {{{"plastic_multiplier", 1, true}},
                      {{"plastic_multiplier", 2, true}}},
                     {});
  expect_logic_error("two couplings, one name",
                     {{}},
                     {{"history", 1, false}, {"history", 1, false}});
  expect_logic_error("a coupling takes a material's name",
                     {plastic.state_fields()},
                     {{"plastic_multiplier", 1, true}});

  // The model's own state: store_state() accumulates the plastic
  // multiplier of each converged update (uniaxial stretch past yield).
  std::array<double, 1> state = {{0.25}};
  Tensor<2, 3>          stretch;
  stretch[0][0] = std::exp(0.05);
  stretch[1][1] = stretch[2][2] = 1.;
  ConstitutiveUpdate update;
  plastic.update(stretch,
                 unit_symmetric_tensor<3>(),
                 ArrayView<const double>(state.data(), state.size()),
                 update);
  plastic.store_state(update, ArrayView<double>(state.data(), state.size()));
  std::cout << "plastic: " << (update.plastic ? "yes" : "no")
            << ", stored multiplier - start - increment = "
            << (std::abs(state[0] - 0.25 - update.plastic_multiplier) < 1e-15 ?
                  "0" :
                  "NONZERO")
            << ", increment > 0: "
            << (update.plastic_multiplier > 0. ? "yes" : "no") << std::endl;
}
