#!/bin/sh
# Usage: contour_checkpoint_parameters.sh <ranks> <mpiexec>
#                                         <shape_from_contour> <work directory>
# A checkpoint of shape_from_contour records the parameters that give its
# state its meaning (doc/shape_from_contour.md, "Checkpoint and resume"):
# a run on levels 4, 5 with 2 and 1 steps writes its checkpoint after step
# 3 (level 5); resumes with another <Model / Mismatch weight>, <Target /
# Radius> or an earlier level of <Multilevel / Levels> are refused with
# exit status 2 and a message naming the parameter and both values; the
# mismatch weight allowed by <Checkpoint / Allow parameter change> resumes
# with a warning, and so does a run that adds level 6 after the
# checkpoint's level.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
# base <directory> <levels> <steps> <more --set ...>
base() {
  dir="$1"; levels="$2"; steps="$3"; shift 3
  run "$ranks" "$program" --set "Multilevel/Levels=$levels" \
    --set "Multilevel/Steps per level=$steps" \
    --set "Checkpoint/Interval=1" --set "Output/VTU interval=0" \
    --set "Output directory=$work/$dir" "$@"
}
base original "4, 5" "2, 1"
expect "the run that writes the checkpoint" 0 "checkpoint written after step 3"
# resume <name> <levels> <steps> <more --set ...>: in a copy of the
# original output directory
resume() {
  name="$1"; shift
  cp -r "$work/original" "$work/$name"
  levels="$1"; steps="$2"; shift 2
  base "$name" "$levels" "$steps" --set "Checkpoint/Resume=true" "$@"
}
checkpoint="checkpoint-3/checkpoint.txt"
resume mismatch_weight "4, 5" "2, 2" --set "Model/Mismatch weight=20"
expect "another mismatch weight" 2 \
  "Cannot resume: <Model / Mismatch weight> = 10 in the checkpoint \(<$work/mismatch_weight/$checkpoint>\), but 20 in this run.*<Checkpoint / Allow parameter change> = Model / Mismatch weight"
resume target_radius "4, 5" "2, 2" --set "Target/Radius=0.3"
expect "another target" 2 \
  "Cannot resume: <Target / Radius> = 0.25 in the checkpoint .*, but 0.29999999999999999 in this run"
resume earlier_level "3, 5" "2, 2"
expect "another earlier level" 2 \
  "Cannot resume: <Multilevel / Levels> = 4, 5 in the checkpoint .*, but 3, 5 in this run"
resume allowed "4, 5" "2, 2" --set "Model/Mismatch weight=20" \
  --set "Checkpoint/Allow parameter change=Model/Mismatch weight"
expect "an allowed change of the mismatch weight" 0 \
  "Warning: resuming with <Model / Mismatch weight> = 10 in the checkpoint .*, but 20 in this run \(allowed by <Checkpoint / Allow parameter change>\)"
resume later_level "4, 5, 6" "2, 1, 1"
expect "a level added after the checkpoint's" 0 "^level 6: h = 0.015625"
exit $failed
