#!/usr/bin/env bash
# The bad-input suite: each case gives the program a mistaken scene or
# command line and checks that it stops with a non-zero exit status (not a
# signal, not the time-out that would catch a hang) and one line
# "Error: ..." naming the problem (a pattern per case), with none of
# deal.II's exception text. On one process that line is all the output; on
# two (MPIEXEC N given) mpiexec may add its own note about the exit status,
# and the cases marked "also_parallel" run there.
# Usage: bad_input.sh IMPM BASE_SCENE [MPIEXEC N]
base=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
parallel=$([ ${#launcher[@]} -gt 0 ] && echo 1 || echo 0)
n_cases=0
n_failed=0

# expect NAME REGEX [also_parallel] -- ARGUMENTS...: run and check one case.
expect() {
  local name=$1 regex=$2 mode=$3
  shift 3
  [ "$1" = "--" ] && shift
  [ "$parallel" = 1 ] && [ "$mode" != also_parallel ] && return
  n_cases=$((n_cases + 1))
  # Each case in a directory of its own (the scenes write to 'results').
  mkdir -p "$work/case_$name" && cd "$work/case_$name" || fail "no case directory"
  timeout 60 "${launcher[@]}" "$impm" "$@" > out.txt 2>&1
  local status=$? problem=""
  if [ $status -eq 0 ]; then problem="exit status 0"
  elif [ $status -eq 124 ]; then problem="no exit within 60 s (a hang)"
  elif [ $status -gt 128 ] && [ "$parallel" = 0 ]; then problem="killed by a signal ($status)"
  fi
  local errors
  errors=$(grep -c "^Error: " out.txt)
  [ "$errors" -eq 1 ] || problem="$problem; $errors lines start with 'Error: '"
  grep -qE "^Error: .*$regex" out.txt || problem="$problem; no error line matching '$regex'"
  grep -qE "An error occurred in line|Stacktrace|Additional information|The violated condition" out.txt &&
    problem="$problem; deal.II's exception text was printed"
  if [ "$parallel" = 0 ]; then
    [ "$(wc -l < out.txt)" -eq 1 ] || problem="$problem; more than one line of output"
  else
    grep -q "MPI_ABORT" out.txt && problem="$problem; the communicator was aborted"
  fi
  if [ -n "$problem" ]; then
    echo "case $name: ${problem#; }"
    sed 's/^/    | /' out.txt | head -12
    n_failed=$((n_failed + 1))
  fi
  cd "$work"
}

# with FILE SED_EXPRESSION: the base scene edited (FILE in $work).
with() { sed -e "$2" "$base" > "$work/$1"; }
# plus FILE TEXT: the base scene with lines appended.
plus() { { cat "$base"; printf '%b\n' "$2"; } > "$work/$1"; }

# Files and syntax.
expect missing_file "Cannot read the scene file 'nothing.prm': No such file" also_parallel -- nothing.prm
: > "$work/empty.prm"
expect empty_file "empty.prm: the scene sets no entry" - -- "$work/empty.prm"
printf '# only a comment\n' > "$work/comment.prm"
expect comment_only "comment.prm: the scene sets no entry" - -- "$work/comment.prm"
plus unknown_entry.prm "set Foo = 1"
expect unknown_entry "unknown_entry.prm:[0-9]+: there is no entry 'Foo' at the top level" - -- "$work/unknown_entry.prm"
with misspelt_entry.prm "s/set Young's modulus/set Youngs modulus/"
expect misspelt_entry "there is no entry 'Youngs modulus' in subsection 'Body 1/Material/von Mises' \(did you mean 'Young's modulus'\?\)" - -- "$work/misspelt_entry.prm"
with unknown_subsection.prm "s/subsection Gravity/subsection Gravty/"
plus nested_subsection.prm "subsection Solver\n subsection Gravity\n end\nend"
expect unknown_nested_subsection "nested_subsection.prm:[0-9]+: there is no subsection 'Gravity' in subsection 'Solver';"  - -- "$work/nested_subsection.prm"
plus empty_value.prm "subsection Gravity\n set Enabled =\nend"
expect empty_value "'Gravity/Enabled' = '' is not allowed: it must be true or false" - -- "$work/empty_value.prm"
expect unknown_subsection "there is no subsection 'Gravty' at the top level \(did you mean 'Gravity'\?\)" - -- "$work/unknown_subsection.prm"
plus missing_end.prm "subsection Solver\n  set Load steps = 4"
expect missing_end "missing_end.prm:[0-9]+: 'subsection Solver' has no matching 'end'" - -- "$work/missing_end.prm"
plus extra_end.prm "end"
expect extra_end "extra_end.prm:[0-9]+: There is no subsection to leave here" - -- "$work/extra_end.prm"
plus not_a_statement.prm "sett Tolerance = 1"
expect not_a_statement "'sett Tolerance = 1' is not a 'set', 'subsection', 'end' or 'include' line" - -- "$work/not_a_statement.prm"
plus no_equals.prm "set Dimension 2"
expect set_without_value "no_equals.prm:[0-9]+: 'set Dimension 2' is not of the form 'set Entry = value'" - -- "$work/no_equals.prm"

# Values against their patterns.
with not_a_number.prm "s/set Tolerance                 = 1e-9/set Tolerance = 1e3x/"
expect not_a_number "not_a_number.prm:[0-9]+: 'Solver/Tolerance' = '1e3x' is not allowed: it must be a number from 1e-15 to 1" also_parallel -- "$work/not_a_number.prm"
with nan.prm "s/set Density                   = 1000/set Density = nan/"
expect nan "'Body 1/Density' = 'nan' is not allowed: it must be a number >= 0" - -- "$work/nan.prm"
with infinite.prm "s/set Upper corner    = 16, 8/set Upper corner = inf, 8/"
expect infinite "'Grid/Upper corner' = 'inf, 8' is not allowed: it must be 2 to 3 comma-separated values, each a number" - -- "$work/infinite.prm"
with subnormal.prm "s/set Density                   = 1000/set Density = 1e-320/"
expect subnormal "'Body 1/Density' = '1e-320' is not allowed: 1e-320 is too close to zero" - -- "$work/subnormal.prm"
with zero_steps.prm "s/set Load steps                = 4/set Load steps = 0/"
expect zero_load_steps "'Solver/Load steps' = '0' is not allowed: it must be an integer >= 1" - -- "$work/zero_steps.prm"
with zero_points.prm "s/set Points per cell direction = 3/set Points per cell direction = 0/"
expect zero_points_per_cell "'Body 1/Points per cell direction' = '0' is not allowed: it must be an integer from 1 to 10" - -- "$work/zero_points.prm"
with dimension.prm "s/set Dimension        = 2/set Dimension = 4/"
expect dimension "'Dimension' = '4' is not allowed: it must be an integer from 2 to 3" - -- "$work/dimension.prm"
with model.prm "s/set Model = von Mises/set Model = von Mizes/"
expect misspelt_model "'Body 1/Material/Model' = 'von Mizes' is not allowed: it must be one of 'Drucker-Prager', 'Hencky elastic', 'Modified Cam-clay', 'Mohr-Coulomb', 'von Mises'" - -- "$work/model.prm"
plus shape.prm "subsection Body 1\n set Shape = circle\nend"
expect unknown_shape "'Body 1/Shape' = 'circle' is not allowed: it must be one of 'box', 'disc', 'sphere', 'polygon'" - -- "$work/shape.prm"
with boolean.prm "s/set Update domains = true/set Update domains = maybe/"
expect not_a_bool "'Material points/Update domains' = 'maybe' is not allowed: it must be true or false" - -- "$work/boolean.prm"
with one_count.prm "s/set Number of cells = 16, 8/set Number of cells = 16/"
expect too_few_numbers "'Grid/Number of cells' = '16' is not allowed: it must be 2 to 3 comma-separated values, each an integer >= 1" - -- "$work/one_count.prm"
with three_counts.prm "s/set Number of cells = 16, 8/set Number of cells = 16, 8, 4/"
expect numbers_for_another_dimension "Parameter 'Grid/Number of cells' = '16, 8, 4' is not allowed: it needs 2 comma-separated numbers \\(one per dimension\\)" - -- "$work/three_counts.prm"
with zero_cells.prm "s/set Number of cells = 16, 8/set Number of cells = 0, 8/"
expect zero_cells "'Grid/Number of cells' = '0, 8' is not allowed: it must be 2 to 3 comma-separated values, each an integer >= 1" - -- "$work/zero_cells.prm"
with corners.prm "s/set Upper corner    = 16, 8/set Upper corner = 16, -1/"
expect inverted_grid "Parameter 'Grid/Upper corner' = '16, -1' is not allowed: each coordinate must exceed" - -- "$work/corners.prm"
with young.prm "s/set Young's modulus = 1e6/set Young's modulus = 0/"
expect zero_young "Parameter 'Body 1/Material/von Mises/Young's modulus' = '0' is not allowed" - -- "$work/young.prm"
# Frictional models and the geostatic start.
plus dilation.prm "subsection Body 1\n subsection Material\n  set Model = Mohr-Coulomb\n  subsection Mohr-Coulomb\n   set Friction angle = 20\n   set Dilation angle = 30\n  end\n end\nend"
expect dilation_above_friction "Parameter 'Body 1/Material/Mohr-Coulomb/Dilation angle' = '30' is not allowed: it must lie in \[0, Friction angle = 20\]" - -- "$work/dilation.prm"
plus residual.prm "subsection Body 1\n subsection Material\n  set Model = Drucker-Prager\n  subsection Drucker-Prager\n   set Hardening modulus = -1e5\n   set Residual cohesion = 2e4\n  end\n end\nend"
expect residual_above_cohesion "Parameter 'Body 1/Material/Drucker-Prager/Residual cohesion' = '2e4' is not allowed: it must lie in \[0, Cohesion = 1e4\]" - -- "$work/residual.prm"
plus kappa.prm "subsection Body 1\n subsection Material\n  set Model = Modified Cam-clay\n  subsection Modified Cam-clay\n   set Lambda = 0.1\n   set Kappa = 0.1\n  end\n end\nend"
expect kappa_not_below_lambda "Parameter 'Body 1/Material/Modified Cam-clay/Kappa' = '0.1' is not allowed: it must lie in \(0, Lambda = 0.1\)" - -- "$work/kappa.prm"
plus tensile.prm "subsection Body 1\n subsection Material\n  set Model = Mohr-Coulomb\n  subsection Mohr-Coulomb\n   set Tension cut-off = true\n   set Tensile strength = -1\n  end\n end\nend"
expect negative_tensile_strength "'Body 1/Material/Mohr-Coulomb/Tensile strength' = '-1' is not allowed: it must be a number >= 0" - -- "$work/tensile.prm"
with f_bar.prm "s/set Basis          = GIMP/set Basis = GIMP\n  set F-bar = yes please/"
expect f_bar_not_a_bool "'Material points/F-bar' = 'yes please' is not allowed: it must be true or false" - -- "$work/f_bar.prm"
plus pressures_without_f_bar.prm "subsection Material points\n set Cell pressure unknowns = true\nend"
expect pressures_without_f_bar "Parameter 'Material points/Cell pressure unknowns' = 'true' is not allowed: cell pressures need 'Material points/F-bar = true'" - -- "$work/pressures_without_f_bar.prm"
plus jump_without_pressures.prm "subsection Material points\n set F-bar = true\n set Pressure jump stabilisation = 0.1\nend"
expect jump_without_pressures "Parameter 'Material points/Pressure jump stabilisation' = '0.1' is not allowed: a stabilisation needs 'Material points/Cell pressure unknowns = true'" - -- "$work/jump_without_pressures.prm"
plus strength.prm "subsection Body 1\n subsection Material\n  set Model = Mohr-Coulomb\n  subsection Mohr-Coulomb\n   set Cohesion = 0\n   set Friction angle = 0\n  end\n end\nend"
expect no_strength "Parameter 'Body 1/Material/Mohr-Coulomb/Cohesion' = '0' is not allowed: with a friction angle of 0 the material has no strength" - -- "$work/strength.prm"
plus geostatic_ramped.prm "subsection Body 1\n set Initial stress = geostatic\nend"
expect geostatic_with_ramped_gravity "Parameter 'Body 1/Initial stress' = 'geostatic' needs gravity along the -y axis acting in full from the first load step" - -- "$work/geostatic_ramped.prm"
plus geostatic_yield.prm "subsection Body 1\n set Initial stress = geostatic\n set K0 = 0.1\nend\nsubsection Gravity\n set Ramped = false\nend"
expect geostatic_outside_yield_surface "Body 1: the geostatic stress with K0 = 0.1 lies outside the yield surface of its material at \(.*\), vertical stress -[0-9.e+]+ Pa" also_parallel -- "$work/geostatic_yield.prm"
plus geostatic_clay.prm "subsection Body 1\n set Initial stress = geostatic\n set Surface level = 7\n subsection Material\n  set Model = Modified Cam-clay\n end\nend\nsubsection Gravity\n set Ramped = false\nend"
expect geostatic_above_surface_cam_clay "Body 1 at \(.*\): Modified Cam-clay cannot start from a stress with p' = 0 Pa <= 0" also_parallel -- "$work/geostatic_clay.prm"
plus surface.prm "subsection Body 1\n set Surface level = top\nend"
expect surface_level_not_a_number "Parameter 'Body 1/Surface level' = 'top' is not allowed: a number" - -- "$work/surface.prm"
with poisson.prm "s/set Poisson's ratio = 0.3/set Poisson's ratio = 0.5/"
expect poisson_half "Poisson's ratio' = '0.5' is not allowed" - -- "$work/poisson.prm"
with tolerance.prm "s/set Tolerance                 = 1e-9/set Tolerance = 0/"
expect zero_tolerance "'Solver/Tolerance' = '0' is not allowed: it must be a number from 1e-15 to 1" - -- "$work/tolerance.prm"
with solver.prm "s/set Tolerance                 = 1e-9/set Linear solver = GMRES/"
expect unknown_solver "'Solver/Linear solver' = 'GMRES' is not allowed: it must be one of 'automatic', 'direct', 'MUMPS', 'GMRES with AMG'" - -- "$work/solver.prm"
with bodies.prm "s/set Dimension        = 2/set Number of bodies = 5/"
expect too_many_bodies "'Number of bodies' = '5' is not allowed: it must be an integer from 1 to 4" - -- "$work/bodies.prm"
plus radius.prm "subsection Body 1\n set Shape = disc\n set Center = 4, 4\n set Radius = 0\nend"
expect zero_radius "Parameter 'Body 1/Radius' = '0' is not allowed: it must be > 0" - -- "$work/radius.prm"
with directory.prm "s/set Output directory = results/set Output directory =/"
expect empty_directory "Parameter 'Output directory' = '' is not allowed: it must not be empty" - -- "$work/directory.prm"

# Entries that contradict each other or the grid.
with outside.prm "s/set Upper corner              = 8, 8/set Upper corner = 8, 9/"
expect body_partly_outside "Body 1 \(\[0 0\] - \[8 9\]\) reaches outside the grid \[0 0\] - \[16 8\] in y" - -- "$work/outside.prm"
with far.prm "s/set Lower corner              = 0, 0/set Lower corner = 20, 0/; s/set Upper corner              = 8, 8/set Upper corner = 28, 8/"
expect body_wholly_outside "Body 1 \(\[20 0\] - \[28 8\]\) reaches outside the grid" - -- "$work/far.prm"
plus overlap.prm "set Number of bodies = 2\nsubsection Body 2\n set Lower corner = 6, 0\n set Upper corner = 10, 4\nend"
expect overlapping_bodies "Body 1 and Body 2 overlap \(both contain \(" also_parallel -- "$work/overlap.prm"
plus empty_body.prm "set Number of bodies = 2\nsubsection Body 2\n set Shape = disc\n set Center = 12.0, 4.0\n set Radius = 0.1\nend"
expect body_without_points "Body 2 \(\[11.9 3.9\] - \[12.1 4.1\]\) holds no material point: none of its 2 x 2 point positions per cell lies inside it" - -- "$work/empty_body.prm"
plus rigid_penalty.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Penalty factor = 0\nend"
expect rigid_zero_penalty "Parameter 'Rigid body 1/Penalty factor' = '0' is not allowed: it must be > 0" - -- "$work/rigid_penalty.prm"
plus rigid_friction.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Friction = coulomb\nend"
expect rigid_coulomb_without_coefficient "Parameter 'Rigid body 1/Friction coefficient' = '0' is not allowed: Coulomb friction needs a coefficient > 0" - -- "$work/rigid_friction.prm"
plus rigid_displacement.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Displacement = 0, -1, 0\nend"
expect rigid_displacement_components "Rigid body 1/Displacement" - -- "$work/rigid_displacement.prm"
plus rigid_force_axis.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Force-driven components = w\nend"
expect rigid_force_component_name "'Rigid body 1/Force-driven components' = 'w' is not allowed: it must be a list of x, y, each at most once" - -- "$work/rigid_force_axis.prm"
plus rigid_held_points.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\nend\nsubsection Material points\n set Move points = false\nend"
expect rigid_with_held_points "'Material points/Move points' = false with a rigid body: .*the points must move" - -- "$work/rigid_held_points.prm"
plus release_without_start.prm "subsection Initial stress release\n set Enabled = true\nend"
expect release_without_initial_stress "'Initial stress release/Enabled' = true, but no body starts from a stress" - -- "$work/release_without_start.prm"
plus release_in_time.prm "subsection Body 1\n set Initial stress = geostatic\nend\nsubsection Gravity\n set Ramped = false\nend\nsubsection Time\n set End time = 1\nend\nsubsection Initial stress release\n set Enabled = true\nend"
expect release_in_time "'Initial stress release/Enabled' = true in a scene with time" - -- "$work/release_in_time.prm"
plus rigid_force_twice.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Force-driven components = y, y\nend"
expect rigid_force_component_twice "'Rigid body 1/Force-driven components' = 'y, y' is not allowed: each component at most once" - -- "$work/rigid_force_twice.prm"
plus rigid_force_undriven.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Force = 0, -5\nend"
expect rigid_force_on_prescribed_component "'Rigid body 1/Force' = '0, -5' is not allowed: a force acts only on the 'Force-driven components' \\(component y is not one\\)" - -- "$work/rigid_force_undriven.prm"
plus rigid_force_moved.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Force-driven components = y\n set Displacement = 0, -1\nend"
expect rigid_force_and_displacement "'Rigid body 1/Displacement' = '0, -1' is not allowed: zero on the 'Force-driven components' \\(component y is one" - -- "$work/rigid_force_moved.prm"
plus rigid_force_floating.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Force-driven components = y\n set Force = 0, -5\nend"
expect rigid_force_floating "Rigid body 1 is pushed by a force \\('Force-driven components'\\) but touches no material at the start" also_parallel -- "$work/rigid_force_floating.prm"
plus rigid_inside.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Shape = disc\n set Center = 4, 7\n set Radius = 2\nend"
expect rigid_body_over_material "starts inside Rigid body 1: a rigid body must start outside the bodies" also_parallel -- "$work/rigid_inside.prm"
plus polygon.prm "subsection Body 1\n set Shape = polygon\n set Vertices = 0, 0; 4, 4; 4, 0; 0, 4\nend"
plus vertex_word.prm "subsection Body 1\n set Shape = polygon\n set Vertices = 0, 0; 4, x; 0, 4\nend"
expect polygon_vertex_not_a_number "Parameter 'Body 1/Vertices' = '0, 0; 4, x; 0, 4' is not allowed: 'x' is not a finite number" - -- "$work/vertex_word.prm"
expect self_intersecting_polygon "Parameter 'Body 1/Vertices' = '0, 0; 4, 4; 4, 0; 0, 4' is not allowed: the polygon's edges 1 and 3 cross" - -- "$work/polygon.prm"
plus repeated_vertex.prm "subsection Body 1\n set Shape = polygon\n set Vertices = 0, 0; 3, 0; 3, 0; 0, 1\nend"
expect polygon_repeated_vertex "Parameter 'Body 1/Vertices' = '0, 0; 3, 0; 3, 0; 0, 1' is not allowed: vertices 2 and 3 coincide." - -- "$work/repeated_vertex.prm"
plus two_vertices.prm "subsection Body 1\n set Shape = polygon\n set Vertices = 0, 0; 4, 4\nend"
expect polygon_two_vertices "a polygon needs at least three vertices" - -- "$work/two_vertices.prm"
{ cat "$(dirname "$base")/column_3d_gimp_plastic_8.prm"; printf 'subsection Body 1\n set Shape = disc\nend\n'; } > "$work/disc_3d.prm"
expect disc_in_3d "'Body 1/Shape' = 'disc' is not allowed: in 3D only box, sphere or cylinder" - -- "$work/disc_3d.prm"
expect axisymmetric_3d "'Grid/Axisymmetric' = 'true' is not allowed: axisymmetry is a 2D option" - -- "$(dirname "$base")/column_3d_gimp_plastic_8.prm" --set "Grid/Axisymmetric=true"
expect axisymmetric_negative_radius "'Grid/Lower corner' = '-1, 0' is not allowed: with Axisymmetric = true x is the radius" - -- "$base" --set "Grid/Axisymmetric=true" --set "Grid/Lower corner=-1, 0"
expect axisymmetric_axis_free "'Grid/Condition x-' = 'none' is not allowed: the grid reaches the axis" also_parallel -- "$base" --set "Grid/Axisymmetric=true" --set "Grid/Condition x-=none"
plus cone_2d.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Shape = cone\nend"
expect cone_in_plane_strain "Rigid body 1/Shape = cone in 2D is the meridian plane of a cone: it needs 'Grid/Axisymmetric' = true" - -- "$work/cone_2d.prm"
expect cone_tip_off_axis "'Rigid body 1/Tip' = '0.5, 2' is not allowed: a cone in 2D is the meridian plane of an axisymmetric one: its tip lies on the axis, x = 0" - -- "$work/cone_2d.prm" --set "Grid/Axisymmetric=true" --set "Rigid body 1/Tip=0.5, 2"
expect cone_axis_across "'Rigid body 1/Axis' = '1, 0' is not allowed: a cone in 2D turns about the grid's axis: its axis is 0, 1 or 0, -1" - -- "$work/cone_2d.prm" --set "Grid/Axisymmetric=true" --set "Rigid body 1/Axis=1, 0"
expect cone_tip_three_numbers "'Rigid body 1/Tip' = '0, 2, 0' is not allowed: it needs 2 comma-separated numbers" - -- "$work/cone_2d.prm" --set "Grid/Axisymmetric=true" --set "Rigid body 1/Tip=0, 2, 0"
{ cat "$(dirname "$base")/column_3d_gimp_plastic_8.prm"; printf 'set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Shape = cone\n set Axis = 0, 0, 0\n set Displacement = 0, 0, 0\nend\n'; } > "$work/cone_axis.prm"
expect cone_without_axis "'Rigid body 1/Axis' = '0, 0, 0' is not allowed: the direction needs a length > 0" - -- "$work/cone_axis.prm"
{ cat "$(dirname "$base")/column_3d_gimp_plastic_8.prm"; printf 'set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Shape = cone\n set Cone radius = 0\n set Displacement = 0, 0, 0\nend\n'; } > "$work/cone_radius.prm"
{ cat "$(dirname "$base")/column_3d_gimp_plastic_8.prm"; printf 'set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Shape = stl\n set STL file = missing.stl\n set Displacement = 0, 0, 0\nend\n'; } > "$work/stl_missing.prm"
expect stl_file_missing "'Rigid body 1/STL file' = '.*missing.stl' is not allowed: cannot open the file" - -- "$work/stl_missing.prm"
{ cat "$(dirname "$base")/column_3d_gimp_plastic_8.prm"; printf 'set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 0, 9\n set Upper corner = 1, 1, 10\n set Rotation = 30\n set Rotation axis = 0, 0, 0\n set Displacement = 0, 0, 0\nend\n'; } > "$work/rotation_axis.prm"
expect rigid_rotation_without_axis "'Rigid body 1/Rotation axis' = '0, 0, 0' is not allowed: the direction needs a length > 0" - -- "$work/rotation_axis.prm"
plus rigid_rotation_range.prm "set Number of rigid bodies = 1\nsubsection Rigid body 1\n set Lower corner = 0, 9\n set Upper corner = 8, 10\n set Rotation = 400\nend"
expect rigid_rotation_out_of_range "Rigid body 1.*Rotation.*400" - -- "$work/rigid_rotation_range.prm"
expect cone_zero_radius "'Rigid body 1/Cone radius' = '0' is not allowed: it must be > 0" - -- "$work/cone_radius.prm"
plus load_outside.prm "subsection Point load\n set Enabled = true\n set Positions = 40, 4\n set Force = 0, -1\nend"
expect point_load_outside_grid "'Point load/Positions': \(40 4\) lies outside the grid \[0 0\] - \[16 8\]" - -- "$work/load_outside.prm"
plus load_far.prm "subsection Point load\n set Enabled = true\n set Positions = 14, 7\n set Force = 0, -1\nend"
expect point_load_off_material "'Point load/Positions': \(14 7\) is [0-9.]+ m from the nearest material point" also_parallel -- "$work/load_far.prm"
with no_support.prm "s/set Condition y-    = roller/set Condition y-    = none/"
expect nothing_holds_y "Nothing holds the material in the y direction" - -- "$work/no_support.prm"
with far_support.prm "s/set Condition y-    = roller/set Condition y+    = roller/; s/set Upper corner    = 16, 8/set Upper corner = 16, 12/; s/set Number of cells = 16, 8/set Number of cells = 16, 12/"
expect support_away_from_material "Nothing holds the material in the y direction" - -- "$work/far_support.prm"
plus region.prm "subsection Grid\n set Region y- = 20, 0, 30, 0\nend"
expect face_region_without_nodes "'Grid/Region y-' = \[20 0\] - \[30 0\] holds no node of the grid face y-" - -- "$work/region.prm"
plus traction_body.prm "subsection Traction\n set Enabled = true\n set Body = 3\nend"
expect traction_on_missing_body "Parameter 'Traction/Body' = 3 is not allowed: the scene has 1 bodies" - -- "$work/traction_body.prm"
plus springs_body.prm "subsection Winkler springs\n set Enabled = true\n set Body = 3\n set Normal stiffness = 1e6\nend"
expect springs_on_missing_body "Parameter 'Winkler springs/Body' = 3 is not allowed: the scene has 1 bodies" - -- "$work/springs_body.prm"
plus springs_stiffness.prm "subsection Winkler springs\n set Enabled = true\nend"
expect springs_without_stiffness "Winkler springs: give a 'Normal stiffness' or a 'Tangential stiffness' above zero" - -- "$work/springs_stiffness.prm"
with huge.prm "s/set Number of cells = 16, 8/set Number of cells = 100000, 100000/"
expect grid_too_large "The scene needs about [0-9.]+ TB \(1e\+10 cells, .* available to the" - -- "$work/huge.prm"

# The command line.
expect set_without_equals "--set 'Solver/Tolerance': expected \"Subsection/Entry=value\"" - -- "$base" --set "Solver/Tolerance"
expect set_unknown_entry "--set 'Solver/Tolerence=1': there is no entry 'Tolerence' in subsection 'Solver' \(did you mean 'Tolerance'\?\)" - -- "$base" --set "Solver/Tolerence=1"
expect set_bad_value "--set 'Solver/Load steps=-2': 'Solver/Load steps' = '-2' is not allowed: it must be an integer >= 1" - -- "$base" --set "Solver/Load steps=-2"
expect largest_below_linear_tolerance "Solver/Largest linear tolerance = 1e-14 is below Solver/Linear tolerance = 1e-12; allowed: from 'Linear tolerance' to 0.5" - -- "$base" --set "Solver/Largest linear tolerance=1e-14"
expect unknown_option "Unknown option '--fast'; see impm --help" - -- "$base" --fast
expect resume_without_checkpoint "--resume: the output directory 'results' holds no complete checkpoint" also_parallel -- "$base" --resume
expect stop_after_zero_steps "--stop-after-step '0': expected a number of load steps from 1 to 1e9" - -- "$base" --stop-after-step 0
expect two_scene_files "Only one scene file may be given" - -- "$base" "$base"
expect missing_library "'Additional shared libraries': cannot load '/nonexistent/libplugin.so': /nonexistent/libplugin.so: cannot open shared object file" also_parallel -- "$base" --set "Additional shared libraries=/nonexistent/libplugin.so"
plus library_in_scene.prm "set Additional shared libraries = no_such_folder/libplugin.so"
expect library_in_scene "cannot load '$work/no_such_folder/libplugin.so'" - -- "$work/library_in_scene.prm"
printf 'set Additional shared libraries = libplugin.so\n' > "$work/libraries.prm"
plus library_included.prm "include $work/libraries.prm"
expect library_included "'Additional shared libraries' = 'libplugin.so' is set where it is read too late \(in a file the scene includes\?\)" - -- "$work/library_included.prm"

# Inertia.
expect inertia_unstable_newmark "Inertia: Newmark gamma = 0.4 with beta = 0.25 is not unconditionally stable: it needs 0.5 <= gamma <= 4 beta" - -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Newmark gamma=0.4"
expect inertia_bad_velocity "Parameter 'Inertia/Initial velocity' = 'sin\\(x' is not allowed: it must be 0 or 2 expressions in x, y separated by ';'" - -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Initial velocity=sin(x"
expect base_shaking_without_time "Base shaking needs time: set 'Time/End time' above 0" - -- "$base" --set "Base shaking/Enabled=true" --set "Base shaking/Acceleration file=x.txt"
expect base_shaking_missing_file "Parameter 'Base shaking/Acceleration file' = 'missing.txt': the file cannot be read." - -- "$base" --set "Time/End time=1" --set "Base shaking/Enabled=true" --set "Base shaking/Acceleration file=missing.txt"
printf '0 0 0\n0.5 1 x\n' > "$work/bad_history.txt"
expect base_shaking_bad_row "line 2 holds 'x', not a number." - -- "$base" --set "Time/End time=1" --set "Base shaking/Enabled=true" --set "Base shaking/Acceleration file=$work/bad_history.txt"
printf '0 0 0\n0 1 0\n' > "$work/repeated_time.txt"
expect base_shaking_repeated_time "the times must increase \\(line 2\\)." - -- "$base" --set "Time/End time=1" --set "Base shaking/Enabled=true" --set "Base shaking/Acceleration file=$work/repeated_time.txt"
expect absorbing_without_time "Absorbing boundary needs time: set 'Time/End time' above 0." - -- "$base" --set "Absorbing boundary/Enabled=true" --set "Absorbing boundary/Density=1" --set "Absorbing boundary/Young's modulus=1"
expect absorbing_without_material "Absorbing boundary: give the 'Density' and 'Young's modulus' \\(> 0\\)" - -- "$base" --set "Time/End time=1" --set "Absorbing boundary/Enabled=true"
expect explicit_above_stable_step "Inertia: the time step 0.5 s is above the stable explicit step .* s \\(Courant number 0.5, smallest cell" - -- "$base" --set "Time/End time=1" --set "Time/Time step=0.5" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL"
# More steps than a run counts (they wrapped to another number, or none),
# a step outside double precision's range for the integrators, and small
# times named as given (not "0.000000").
expect time_steps_beyond_count "Parameter 'Time/Time step' = 1e-09 over 'Time/End time' = 10 gives 1e\\+10 steps, more than a run can count \\(4294967295\\): take a larger time step." - -- "$base" --set "Time/End time=10" --set "Time/Time step=1e-9"
expect time_step_beyond_range "'Time/End time' = 1e\\+300 in 100 steps gives a time step of 1e\\+298 s, outside the range of 1e-150 to 1e150 s" - -- "$base" --set "Time/End time=1e300" --set "Solver/Load steps=100" --set "Inertia/Enabled=true"
expect time_step_above_end_small "Parameter 'Time/Time step' = 2e-05 is not allowed: it must be at most 'Time/End time' = 1e-05." - -- "$base" --set "Time/End time=1e-5" --set "Time/Time step=2e-5"
expect explicit_with_dashpots "Absorbing boundary: its dashpots act on the step's mean velocity, which an explicit step does not solve for" - -- "$base" --set "Time/End time=1" --set "Time/Time step=0.01" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" --set "Absorbing boundary/Enabled=true" --set "Absorbing boundary/Density=1" --set "Absorbing boundary/Young's modulus=1"
expect explicit_cell_pressures "Material points/Cell pressure unknowns: the cell pressures are unknowns of the load step's system, which an explicit step does not solve" - -- "$base" --set "Time/End time=1" --set "Time/Time step=0.01" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" --set "Material points/F-bar=true" --set "Material points/Cell pressure unknowns=true"
expect explicit_force_driven "Rigid body 1: 'Force-driven components' make its displacement an unknown of the load step's system, which an explicit step does not solve" - -- "$(dirname "$base")/contact_plate_force_driven.prm" --set "Time/End time=1" --set "Time/Time step=0.0001" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit USL"
expect explicit_springs_above_stable_step "Inertia: the time step 0.005 s is above the stable explicit step 0.00070014 s \\(Courant number 0.5, smallest cell 1 m, speed of sound 714.143 m/s, with springs of 1e\\+09 Pa/m on faces\\)" - -- "$(dirname "$base")/winkler_springs_layer.prm" --set "Time/End time=0.5" --set "Time/Time step=0.005" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" --set "Winkler springs/Normal stiffness=1e9"
expect inertia_consistent_explicit "Inertia: 'Mass' = 'consistent' needs an implicit integrator" - -- "$base" --set "Time/End time=1" --set "Time/Time step=0.01" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" --set "Inertia/Mass=consistent"
expect mass_ghost_explicit "Inertia: 'Mass ghost penalty' acts on the matrix of the implicit integrators; an explicit one has none" - -- "$base" --set "Time/End time=1" --set "Time/Time step=0.01" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" --set "Inertia/Mass ghost penalty=0.1"
expect point_history_region "Point history: 'Region lower corner' must lie below 'Region upper corner' in every coordinate" - -- "$base" --set "Point history/Region lower corner=2, 2" --set "Point history/Region upper corner=1, 3"
# A followed position off the grid (its nearest point a corner of a body,
# followed silently) and a region without points (an empty history).
expect point_history_off_grid "'Point history/Positions': \\(1e\\+09 1\\) lies outside the grid \\[0 0\\] - \\[16 8\\]." also_parallel -- "$base" --set "Point history/Positions=1, 1; 1e9, 1"
expect point_history_empty_region "'Point history/Region lower corner' and 'Region upper corner': the box \\[15 7\\] - \\[16 8\\] holds no material point at the start." also_parallel -- "$base" --set "Point history/Region lower corner=15, 7" --set "Point history/Region upper corner=16, 8"
expect local_damping_implicit "Inertia: 'Local damping' needs an explicit integrator" - -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Local damping=0.5"
expect initial_velocity_not_finite "Parameter 'Inertia/Initial velocity' = 'sqrt\\(-1 - x\\); 0' gives a velocity that is not finite \\(-?nan\\) at the point initially at \\(" also_parallel -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Initial velocity=sqrt(-1 - x); 0"
expect apic_with_flip "Inertia: 'FLIP fraction' = 0.9 blends FLIP with PIC; with 'Velocity update' = 'APIC'" - -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Velocity update=APIC" --set "Inertia/FLIP fraction=0.9"
expect apic_consistent_mass "Inertia: 'Velocity update' = 'APIC' needs 'Mass' = 'lumped'" - -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Velocity update=APIC" --set "Inertia/Mass=consistent"
expect apic_explicit_standard_mpm "Inertia: 'Velocity update' = 'APIC' with an explicit integrator needs 'Material points/Basis' = 'GIMP'" - -- "$base" --set "Time/End time=1" --set "Time/Time step=0.01" --set "Inertia/Enabled=true" --set "Inertia/Integrator=explicit MUSL" --set "Inertia/Velocity update=APIC" --set "Material points/Basis=standard MPM"
# Strength reduction.
expect strength_reduction_elastic "Strength reduction: no body's material has a strength to reduce \\(the bodies are elastic\\)" - -- "$base" --set "Body 1/Material/Model=Hencky elastic" --set "Strength reduction/Enabled=true"
expect strength_reduction_resume "A strength reduction cannot be resumed: its trials are whole runs of the scene" also_parallel -- "$base" --set "Strength reduction/Enabled=true" --resume
expect strength_reduction_face_motion "Strength reduction: 'Grid/Displacement y\\+' prescribes a motion, which moves the material whatever its strength" - -- "$base" --set "Strength reduction/Enabled=true" --set "Grid/Condition y+=prescribed" --set "Grid/Displacement y+=0, -0.01"
expect strength_reduction_rigid_motion "Strength reduction: 'Rigid body 1/Displacement' prescribes a motion" - -- "$(dirname "$base")/contact_plate_compression_3d.prm" --set "Strength reduction/Enabled=true" --set "Body 1/Material/Model=von Mises"
expect region_on_free_face "'Grid/Region y\\+' limits 'Condition y\\+' to a part of the face, but the condition is none" also_parallel -- "$base" --set "Grid/Region y+=0, 8, 16, 8"
expect face_displacement_not_prescribed "'Grid/Displacement y\\+' is not zero, but 'Condition y\\+' does not prescribe the face's motion" also_parallel -- "$base" --set "Grid/Condition y+=fixed" --set "Grid/Displacement y+=0, -0.01"
mkdir -p "$work/a_directory.prm"
expect scene_is_directory "Cannot read the scene file '.*a_directory.prm': it is a directory\\." - -- "$work/a_directory.prm"
expect body_field_one_body "Output/Fields names 'body', which a scene of one body does not store" - -- "$base" --set "Output/Interval=1" --set "Output/Fields=stress, body"
expect prescribed_normal_tangential "'Grid/Displacement x\\+' has a y component, which 'Grid/Condition x\\+' = 'prescribed normal' does not move \\(it moves the x component only\\)" - -- "$(dirname "$base")/energy_balance_pulled_bar.prm" --set "Grid/Displacement x+=0.1, 0.05"
expect strength_reduction_held_points "'Strength reduction/Enabled' = 'true' needs 'Material points/Move points' = true" - -- "$(dirname "$base")/strength_reduction_block.prm" --set "Material points/Move points=false"
expect strength_reduction_inertia "'Strength reduction/Enabled' = 'true' needs a quasi-static scene" - -- "$base" --set "Strength reduction/Enabled=true" --set "Time/End time=1" --set "Inertia/Enabled=true"
expect inertia_without_time "Inertia needs time: set 'Time/End time' above 0 \\(the load steps are then time steps\\)." - -- "$base" --set "Inertia/Enabled=true"
expect time_step_without_end_time "Parameter 'Time/Time step' = 0.1 needs 'Time/End time' above 0" - -- "$base" --set "Time/Time step=0.1"
expect time_step_above_end_time "Parameter 'Time/Time step' = 2 is not allowed: it must be at most 'Time/End time' = 1." - -- "$base" --set "Time/End time=1" --set "Time/Time step=2"
expect load_factor_without_time "Parameter 'Time/Load factor' = 't' needs 'Time/End time' above 0" - -- "$base" --set "Time/Load factor=t"
expect load_factor_bad_expression "Parameter 'Time/Load factor' = 'sin\\(t' is not allowed: it must be an expression in t" - -- "$base" --set "Time/End time=1" --set "Time/Load factor=sin(t"
expect load_factor_infinite "Parameter 'Time/Load factor' = '1/t' is not allowed: it must be an expression in t" - -- "$base" --set "Time/End time=1" --set "Time/Load factor=1/t"
# A load factor not 0 at t = 0 would lose its share of a prescribed face's
# displacement or a rigid body's motion (they start from the initial
# state): refused, naming the face or the body.
expect load_factor_start_face "Parameter 'Time/Load factor' = '1' is 1 at t = 0, but the displacement of face x\+ \('Grid/Condition x\+'\) starts from the scene's initial state" - -- "$(dirname "$base")/energy_balance_pulled_bar.prm" --set "Time/Load factor=1"
expect load_factor_start_body "Parameter 'Time/Load factor' = '0.5 \+ t' is 0.5 at t = 0, but the motion of Rigid body 1 starts from the scene's initial state" - -- "$(dirname "$base")/contact_plate_compression.prm" --set "Time/End time=1" --set "Time/Load factor=0.5 + t"
# The material test: a path the model cannot follow ends in one line
# naming the step (Cam-clay's void ratio through 0 under 1.0e8 Pa; an
# initial stress whose deviator overflows; a kappa whose trial pressure
# overflows), not a row of negative void ratios or infinite stresses with
# exit code 0, nor an "Internal error".
expect material_test_void_ratio "Material test: step 208 of 300 \\(driven strain 0.693333\\): the void ratio fell to -0.000186135 at p' = 1.02559e\\+08 Pa" - -- "$(dirname "$base")/material_test_cam_clay_drained.prm" --set "Material test/Path=oedometer" --set "Material test/Strain=1" --set "Material test/Number of steps=300" --set "Material test/File=oedometer.csv"
expect material_test_overflow "Material test: step 1 of 300 \\(driven strain 0.001\\): the stress is not finite" - -- "$(dirname "$base")/material_test_cam_clay_drained.prm" --set "Material test/Initial vertical stress=1e300" --set "Material test/Strain=0.3" --set "Material test/Number of steps=300" --set "Material test/File=overflow.csv"
expect material_test_update_failed "Material test: step 1 of 6000 \\(driven strain 0.0002\\): the material's update failed, in one step and in up to 64 sub-steps: Modified Cam-clay: the trial mean stress over- or underflows" - -- "$(dirname "$base")/material_test_cam_clay_drained.prm" --set "Body 1/Material/Modified Cam-clay/Kappa=1e-9" --set "Material test/File=kappa.csv"
expect axisymmetric_radial_shaking "Parameter 'Base shaking/Acceleration file' = '.*base_shaking_ramp.txt' has a radial \\(first\\) component, which an axisymmetric scene cannot carry" - -- "$(dirname "$base")/base_shaking_ramp.prm" --set "Grid/Axisymmetric=true" --set "Grid/Condition x-=roller" --set "Body 1/Lower corner=0, 0" --set "Base shaking/Acceleration file=$(dirname "$base")/base_shaking_ramp.txt"
expect inertia_velocity_in_time "Parameter 'Inertia/Initial velocity' = 't; 0' is not allowed: it must be 0 or 2 expressions in x, y separated by ';'" also_parallel -- "$base" --set "Time/End time=1" --set "Inertia/Enabled=true" --set "Inertia/Initial velocity=t; 0"

# Declared point state: a field no point stores; a checkpoint resumed into
# points laid out otherwise (the plastic model's state, then an elastic
# model without it): refused as a changed scene, and with
# --resume-with-changes by the points' layout.
expect unknown_point_field "Output/Fields names 'plastic_multipler', which this scene's points do not store; its fields are displacement, .*, plastic_multiplier\\." - -- "$base" --set "Output/Interval=1" --set "Output/Fields=stress, plastic_multipler"
mkdir -p "$work/case_resume_other_layout" && (cd "$work/case_resume_other_layout" &&
  "$impm" "$base" --set "Checkpoint/Interval=1" --stop-after-step 1 > first.txt 2>&1) ||
  fail "the run that writes the checkpoint failed"
mkdir -p "$work/case_resume_changed_scene" &&
  cp -a "$work/case_resume_other_layout/results" "$work/case_resume_changed_scene/" ||
  fail "the checkpoint could not be copied"
expect resume_changed_scene "--resume: the scene differs from the one the checkpoint was written from in 1 entry: 'Body 1/Material/Model' von Mises -> Hencky elastic" also_parallel -- "$base" --set "Body 1/Material/Model=Hencky elastic" --resume
expect resume_other_layout "The checkpoint's material points store 3[0-9] properties; body 1: plastic_multiplier\\(1\\), this scene's 2[0-9] properties: resume with the scene" also_parallel -- "$base" --set "Body 1/Material/Model=Hencky elastic" --resume-with-changes

# Contradictions in a scene.
expect zero_density "'Body 1/Density' = 0: a body needs a density above 0\." also_parallel -- "$base" --set "Body 1/Density=0"
expect column_solution_elsewhere "'Output/Analytical solution' = column describes a column under its own weight \(one box body, gravity along the last axis\), but no gravity acts along the last axis: set it to none" also_parallel -- "$base" --set "Output/Analytical solution=column" --set "Gravity/Enabled=false"
expect rigid_body_outside_grid "Rigid body 1 \\(.*\\) lies outside the grid .* in x and its 'Displacement' does not bring it in: a rigid body must reach the grid" also_parallel -- "$base" --set "Number of rigid bodies=1" --set "Rigid body 1/Lower corner=1e6, 0" --set "Rigid body 1/Upper corner=1000001, 1"
expect fixed_and_prescribed "The nodes on the edge of grid faces x- and y\\+ are both held \\('Grid/Condition x-' holds their y displacement at 0\\) and moved \\('Grid/Condition y\\+' prescribes it\\)" also_parallel -- "$base" --set "Grid/Condition x-=fixed" --set "Grid/Condition y+=prescribed" --set "Grid/Displacement y+=0, -0.1"
# A UTF-8 byte-order mark at the start of a scene is skipped: the scene runs.
if [ "$parallel" = 0 ]; then
  n_cases=$((n_cases + 1))
  { printf '\xef\xbb\xbf'; cat "$base"; } > "$work/bom.prm"
  mkdir -p "$work/case_bom" && cd "$work/case_bom" || fail "no case directory"
  timeout 60 "$impm" "$work/bom.prm" --stop-after-step 1 > out.txt 2>&1 &&
    grep -q "^Stopped after load step 1" out.txt || {
    echo "case byte_order_mark: the scene with a byte-order mark did not run"
    sed 's/^/    | /' out.txt | head -12
    n_failed=$((n_failed + 1))
  }
  cd "$work"
fi

# The material test without a grid ('Material test'): wrong paths and
# values, a file it cannot write.
mt=(--set "Material test/Enabled=true")
expect material_test_path "'Material test/Path' = 'triaxial' is not allowed: it must be one of 'drained triaxial compression'" - -- "$base" "${mt[@]}" --set "Material test/Path=triaxial"
expect material_test_cyclic_path "'Material test/Cyclic path' = 'cyclic' is not allowed: it must be one of 'drained triaxial', 'undrained triaxial', 'oedometer', 'simple shear'" - -- "$base" "${mt[@]}" --set "Material test/Cyclic path=cyclic"
expect material_test_cyclic_steps "Parameter 'Material test/Number of steps' = '10' is not allowed: a cyclic path needs a multiple of 4 steps per cycle." - -- "$base" "${mt[@]}" --set "Material test/Path=cyclic" --set "Material test/Number of steps=10"
expect material_test_zero_strain "Parameter 'Material test/Strain' = '0' is not allowed: it must be > 0." - -- "$base" "${mt[@]}" --set "Material test/Strain=0"
expect material_test_zero_k0 "Parameter 'Material test/K0' = '0' is not allowed: it must be > 0." - -- "$base" "${mt[@]}" --set "Material test/K0=0"
expect material_test_measure "'Material test/Stress measure' = 'PK2' is not allowed: it must be one of 'Cauchy', 'Kirchhoff'" - -- "$base" "${mt[@]}" --set "Material test/Stress measure=PK2"
mkdir -p "$work/case_material_test_file" && : > "$work/case_material_test_file/a_file"
expect material_test_file "Material test: cannot write the file '$work/case_material_test_file/a_file/test.csv' \\('Material test/File'\\)." - -- "$base" "${mt[@]}" --set "Material test/File=$work/case_material_test_file/a_file/test.csv"

# The output directory.
mkdir -p "$work/case_directory_of_another_run/other" && printf 'scene = another\nscene file = /elsewhere/another.prm\n' > "$work/case_directory_of_another_run/other/impm-run.txt"
with other_run.prm "s/set Output directory = results/set Output directory = other/"
expect directory_of_another_run "The output directory 'other' holds the run of scene 'another' \(/elsewhere/another.prm\)" also_parallel -- "$work/other_run.prm"
mkdir -p "$work/case_directory_cannot_be_created" && : > "$work/case_directory_cannot_be_created/a_file"
with blocked.prm "s/set Output directory = results/set Output directory = a_file\/results/"
expect directory_cannot_be_created "Cannot create the output directory 'a_file/results' \('Output directory'\)" also_parallel -- "$work/blocked.prm"

echo "bad_input: $n_cases cases, $n_failed failed"
[ "$n_failed" -eq 0 ] || fail "$n_failed of $n_cases bad inputs were not reported as they should be"
[ "$parallel" = 1 ] || [ "$n_cases" -ge 40 ] || fail "fewer than 40 cases"
