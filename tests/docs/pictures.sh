#!/bin/sh
# Usage: pictures.sh <source directory> <build directory> <work directory>
# Every PNG picture that the programs write shows something: willmore_flow
# in 2D (phase_field.png, the quarter circle), edge_restoration
# (initial.png and restored.png, the cross) and shape_from_contour in 2D
# (contour_level_5.png, the disc of Fig. 6.5), each made small by --set
# and run on 1 rank; willmore_flow in 3D (surface.png, the cube of Fig.
# 5.4) and shape_from_contour in 3D (contour_level_5.png and
# body_level_5.png, the sphere of Fig. 6.10), run on 1 and on 2 ranks,
# whose pictures must have the same pixels (check_png.py --same).
# tests/docs/check_png.py fails for a missing, blank or constant
# picture. Runs in the source directory (the files name their images
# relative to it) with the output in <work directory>.
source_dir="$1"; build_dir="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
cd "$source_dir" || exit 1
failed=0
run() {
  echo "== $*"
  if ! OMP_NUM_THREADS=1 timeout 120 "$@" > "$work/log" 2>&1; then
    echo "FAIL (status $?): $*"; tail -20 "$work/log"; failed=1
  fi
}
run "$build_dir/willmore_flow" parameter_files/willmore_flow/quarter_circle_h7.prm \
  --set "Mesh/Finest level=5" --set "Time stepping/Number of steps=2" \
  --set "Phase field/Epsilon=4*h" --set "Output directory=$work/willmore"
run "$build_dir/edge_restoration" parameter_files/edge_restoration/cross.prm \
  --set "Mesh/Finest level=5" --set "Time stepping/Number of steps=1" \
  --set "Output directory=$work/restoration"
run "$build_dir/shape_from_contour" parameter_files/shape_from_contour/fig6_5_disc.prm \
  --set "Multilevel/Levels=5" --set "Multilevel/Steps per level=1" \
  --set "Output directory=$work/contour"
for ranks in 1 2; do
  mpi="mpirun --allow-run-as-root -np $ranks"
  run $mpi "$build_dir/willmore_flow" parameter_files/willmore_flow/cube.prm \
    --set "Mesh/Finest level=5" --set "Time stepping/Number of steps=1" \
    --set "Output/Surface format=none" --set "Output/VTU interval=0" \
    --set "Output directory=$work/willmore_3d_$ranks"
  run $mpi "$build_dir/shape_from_contour" parameter_files/shape_from_contour/fig6_10_sphere.prm \
    --set "Multilevel/Levels=5" --set "Multilevel/Steps per level=1" \
    --set "Output/VTU interval=0" --set "Output directory=$work/contour_3d_$ranks"
done
/usr/bin/python3 "$source_dir/tests/docs/check_png.py" \
  "$work/willmore/phase_field.png" "$work/restoration/initial.png" \
  "$work/restoration/restored.png" "$work/contour/contour_level_5.png" \
  "$work/willmore_3d_1/surface.png" "$work/willmore_3d_2/surface.png" \
  "$work/contour_3d_1/contour_level_5.png" "$work/contour_3d_1/body_level_5.png" \
  "$work/contour_3d_2/body_level_5.png" || failed=1
for picture in willmore_3d_%/surface.png contour_3d_%/body_level_5.png; do
  /usr/bin/python3 "$source_dir/tests/docs/check_png.py" --same \
    "$work/$(echo $picture | sed s/%/1/)" "$work/$(echo $picture | sed s/%/2/)" || failed=1
done
[ $failed -eq 0 ] && echo "OK: every picture shows something"
exit $failed
