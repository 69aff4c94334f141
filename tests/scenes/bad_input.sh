#!/bin/bash
# Bad input must give a clear message naming the parameter (or file), a
# non-zero exit status, and write nothing (no output directory).
# Usage: bad_input.sh <fsgmpm executable> <tests source dir>
set -u
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
passed=0

# How fsgmpm is started: serially, or (below) with mpirun; a run that does
# not stop within 120 s hangs.
runner=(timeout 120)

# expect_error <name> <regex the message must match> <fsgmpm arguments...>
expect_error() {
  local name=$1 pattern=$2
  shift 2
  rm -rf out
  "${runner[@]}" "$exe" "$@" --set "Output/Directory=out" >stdout.txt 2>stderr.txt
  local status=$?
  local msg
  msg=$(cat stdout.txt stderr.txt)
  if [ $status -eq 0 ]; then
    echo "FAIL $name: exit status 0"; failures=$((failures + 1)); return
  fi
  if [ $status -eq 124 ]; then
    echo "FAIL $name: hangs (no exit within 120 s)"; failures=$((failures + 1)); return
  fi
  if ! grep -Eq "$pattern" <<<"$msg"; then
    echo "FAIL $name: message does not match /$pattern/:"; echo "$msg"
    failures=$((failures + 1)); return
  fi
  if [ -e out ]; then
    echo "FAIL $name: output was written"; failures=$((failures + 1)); return
  fi
  if grep -q "Stacktrace\|Segmentation\|Aborted" <<<"$msg"; then
    echo "FAIL $name: crashed"; failures=$((failures + 1)); return
  fi
  echo "ok   $name: $(head -c 300 stderr.txt | tr '\n' ' ')"
  passed=$((passed + 1))
}

cat > unknown.prm <<'PRM'
subsection Simulation
  set End tme = 1
end
PRM
expect_error "unknown parameter in prm" "Line 2 of <unknown.prm>: there is no entry <End tme> in subsection <Simulation>. Did you mean <End time>\?" unknown.prm
expect_error "unknown parameter in --set" "no parameter <Simulation/End tme>. Did you mean <Simulation/End time>\?" --set "Simulation/End tme=1"
expect_error "unknown subsection in --set" "no parameter <Simulaton/End time>. Did you mean <Simulation/End time>\?" --set "Simulaton/End time=1"
cat > unknown_subsection.prm <<'PRM'
subsection Simulaton
  set End time = 1
end
PRM
expect_error "unknown subsection in prm" "Line 1 of <unknown_subsection.prm>: there is no subsection <Simulaton> at the top level. Did you mean <Simulation>\?" unknown_subsection.prm
cat > missing_end.prm <<'PRM'
subsection Simulation
  set End time = 1
subsection Grid
  set Type = box
end
PRM
expect_error "missing end before a subsection" "Line 3 of <missing_end.prm>: there is no subsection <Grid> in subsection <Simulation>. Is the <end> of subsection <Simulation> \(opened at line 1\) missing above it\?" missing_end.prm
cat > missing_last_end.prm <<'PRM'
subsection Simulation
  set End time = 1
PRM
expect_error "missing end at the end of the file" "the file ends with subsection <Simulation> still open: the <end> of subsection <Simulation> \(opened at line 1\) is missing" missing_last_end.prm
cat > extra_end.prm <<'PRM'
subsection Simulation
  set End time = 1
end
end
PRM
expect_error "end without a subsection" "Line 4 of <extra_end.prm>: <end> with no subsection open" extra_end.prm
cat > wrong_subsection.prm <<'PRM'
subsection Grid
  set Courant number = 0.3
end
PRM
expect_error "entry in the wrong subsection" "there is no entry <Courant number> in subsection <Grid>. It is an entry in subsection <Simulation>" wrong_subsection.prm
cat > no_equals.prm <<'PRM'
subsection Simulation
  set End time 1
end
PRM
expect_error "set without =" "Line 2 of <no_equals.prm>: <set End time 1> has no <=>" no_equals.prm
expect_error "negative density" "Bodies/Body 0/Density|Density" --set "Bodies/Body 0/Density=-1000"
expect_error "nu = 0.5" "Poisson's ratio" "$2/../prm/elastic_block_drop.prm" --set "Bodies/Body 0/Linear elastic/Poisson's ratio=0.5"
expect_error "f_c = 1" "Free surface threshold" --set "Bodies/Body 0/Free surface threshold=1"
expect_error "negative bulk modulus" "Bulk modulus" --set "Bodies/Body 0/Newtonian fluid/Bulk modulus=-2e9"
expect_error "positive tension cut-off" "Tension cut-off" --set "Bodies/Body 0/Newtonian fluid/Tension cut-off=1e3"
expect_error "tension cut-off with Allow tension" "Allow tension = true lets the fluid pull without limit, and Tension cut-off sets a limit" --set "Bodies/Body 0/Newtonian fluid/Tension cut-off=-1e5" --set "Bodies/Body 0/Newtonian fluid/Allow tension=true"
expect_error "unknown material" "Material model" --set "Bodies/Body 0/Material model=honey"
expect_error "NMD with the nodal stress projection" "Volumetric smoothing = NMD\+ANP cannot be combined" --set "Simulation/Stress integration=nodal projection" --set "Bodies/Body 0/Volumetric smoothing=NMD+ANP"
expect_error "3D slip on a Gmsh membrane" "slip needs a 2D membrane or, in 3D, an extruded one" "$2/../prm/geotube_A5.56_3d.prm" --set "Membrane/Shape=gmsh"
expect_error "membrane DataOut in HDF5" "Membrane output = finite elements is written as VTU" "$2/../prm/geotube_A5.56.prm" --set "Output/Format=hdf5" --set "Output/Membrane output=finite elements"
expect_error "missing Gmsh membrane" "Membrane/Mesh file: cannot open the Gmsh file <no_such_membrane.msh>" "$2/../prm/geotube_A5.56_3d.prm" --set "Membrane/Shape=gmsh" --set "Membrane/Tangential coupling=no-slip" --set "Membrane/Mesh file=no_such_membrane.msh"
expect_error "Gmsh membrane of tetrahedra" "type 4; a membrane surface consists of 3-node or 6-node triangles" "$2/../prm/geotube_A5.56_3d.prm" --set "Membrane/Shape=gmsh" --set "Membrane/Tangential coupling=no-slip" --set "Membrane/Mesh file=$2/meshes/cube_tetrahedra.msh"
expect_error "Gmsh membrane shorter than the grid" "but the surface spans only z in \[0, 0.16\]" "$2/../prm/geotube_A5.56_3d.prm" --set "Membrane/Shape=gmsh" --set "Membrane/Tangential coupling=no-slip" --set "Membrane/Mesh file=$2/meshes/geotube_A5.56_p1.msh" --set "Grid/Extrusion thickness=0.32"
expect_error "unknown velocity transfer" "Velocity transfer" --set "Simulation/Velocity transfer=PIC"
expect_error "affine remap with USL" "APIC affine remap.*USL" --set "Simulation/Velocity transfer=APIC affine remap" --set "Simulation/Update scheme=USL"
expect_error "XPIC order without the noise relaxation" "XPIC order = 4 sets the velocity FLIP.s noise relaxes to" --set "Simulation/XPIC order=4"
expect_error "XPIC order with APIC" "XPIC order = 2 sets" --set "Simulation/XPIC order=2" --set "Simulation/FLIP noise relaxation time=0.01" --set "Simulation/Velocity transfer=APIC"
expect_error "body outside the mesh" "Body 0.*outside the background mesh" --set "Bodies/Body 0/Box upper corner=1.5, 0.4"
expect_error "missing mesh file" "no_such_mesh.msh" --set "Grid/Type=gmsh" --set "Grid/Mesh file=no_such_mesh.msh"
expect_error "missing prm file" "no_such_file.prm" no_such_file.prm
expect_error "Courant number > 1" "Courant number" --set "Simulation/Courant number=1.5"
expect_error "bad wall type" "Grid/Boundary conditions" --set "Grid/Boundary conditions=0: sticky"
expect_error "wrong vector length" "Bodies/Body 0/Box lower corner" --set "Bodies/Body 0/Box lower corner=0.3"
expect_error "bad particles per cell" "Particles per cell" --set "Bodies/Body 0/Particles per cell=5"
expect_error "self-intersecting polygon" "Bodies/Body 0/Polygon vertices: The polygon intersects itself" --set "Bodies/Body 0/Shape=polygon" --set "Bodies/Body 0/Polygon vertices=0.3,0.2; 0.6,0.4; 0.6,0.2; 0.3,0.4"
expect_error "zero column aspect ratio" "invalid value <0> for <Bodies/Body 0/Column aspect ratio>: .*\(0 exclusive" --set "Bodies/Body 0/Shape=column" --set "Bodies/Body 0/Column aspect ratio=0"
expect_error "friction angle >= 90" "Friction angle" "$2/../prm/granular_column_collapse.prm" --set "Bodies/Body 0/Mohr-Coulomb/Friction angle=95"
expect_error "dilatancy above friction" "Dilatancy angle must lie in" "$2/../prm/granular_column_collapse.prm" --set "Bodies/Body 0/Mohr-Coulomb/Dilatancy angle=40"
expect_error "volume cap not above 1" "invalid value <1> for <Bodies/Body 0/Mohr-Coulomb/Maximum volume ratio>: .*\(1 exclusive" "$2/../prm/granular_column_collapse.prm" --set "Bodies/Body 0/Mohr-Coulomb/Maximum volume ratio=1"
expect_error "unknown option" "Unknown option" --frobnicate
g="$2/../prm/geotube_A5.56.prm"
expect_error "membrane area above the circle's" "Membrane/Circumference and Enclosed area: .*cannot enclose" "$g" --set "Membrane/Enclosed area=7"
expect_error "membrane outside the mesh" "Membrane node .* lies outside the mesh" "$g" --set "Membrane/Lowest point=5.5, 0"
expect_error "fill a missing membrane" "Shape = membrane needs a membrane" "$g" --set "Membrane/Enabled=false" --set "Monitors/Scene monitors="
expect_error "self-intersecting membrane" "Membrane/Polygon vertices: The polygon intersects itself" "$g" --set "Membrane/Shape=polygon" --set "Membrane/Polygon vertices=1,1; 2,2; 2,1; 1,2"
expect_error "zero membrane stiffness" "Axial stiffness" "$g" --set "Membrane/Axial stiffness=0"
expect_error "membrane fill in velocity field 1" "Bodies/Body 0/Shape = membrane needs Velocity field = 0" "$2/../prm/geocontainer_polygon.prm" --set "Bodies/Body 0/Velocity field=1"
expect_error "unknown material model" "Material model.*does not match" --set "Bodies/Body 0/Material model=Drucker-Prager"
expect_error "ground level not a number" "Membrane/Ground level must be a number or none" "$g" --set "Membrane/Ground level=floor"
expect_error "unknown scene monitor" "Scene monitors.*front_positon.*dam_break" --set "Monitors/Scene monitors=front_positon"
expect_error "geotube monitor without a membrane" "Scene monitors: height \(scene monitor geotube\) needs a membrane" --set "Monitors/Scene monitors=height"

w="$2/../prm/water_column_collapse_n2.prm"
expect_error "gate off the grid lines" "Moving wall/Lower corner and Upper corner: the wall's plane x = 0.115 holds no grid node" "$w" --set "Moving wall/Enabled=true" --set "Moving wall/Lower corner=0.115, 0" --set "Moving wall/Upper corner=0.115, 0.3"
expect_error "gate pushed along its normal" "Moving wall/Velocity history: <0: 1 2> moves the wall along its normal" "$w" --set "Moving wall/Enabled=true" --set "Moving wall/Velocity history=0: 1 2"
expect_error "repartition imbalance below 1" "Simulation/Repartition imbalance is the ratio .* at least 1 .*got 0.5" --set "Simulation/Repartition imbalance=0.5"

# MPI: an error found on process 0 at the start (which alone holds the whole
# grid) stops every process with the message and a non-zero exit status
# (MPI_Abort), never a hang of the processes waiting for their windows.
if ! command -v mpirun >/dev/null; then
  echo "FAIL MPI cases: no mpirun (Debian package openmpi-bin)"
  failures=$((failures + 1))
else
  source "$2/mpi/mpi_launch.sh"
  runner=(timeout 120 mpirun --oversubscribe -np 2)
  expect_error "MPI: body outside the mesh" "Body 0.*outside the background mesh" --set "Bodies/Body 0/Box upper corner=1.5, 0.4"
  expect_error "MPI: unknown boundary id" "Grid/Boundary conditions names boundary id 7" --set "Grid/Boundary conditions=7: slip"
  expect_error "MPI: membrane outside the mesh" "Membrane node .* lies outside the mesh" "$g" --set "Membrane/Lowest point=5.5, 0"
fi

echo "bad input: $passed passed, $failures failed"
[ $failures -eq 0 ]
