#!/bin/sh
# Usage: restoration_checkpoint_parameters.sh <ranks> <mpiexec>
#                                             <edge_restoration> <work directory>
# A checkpoint of edge_restoration records the parameters that give its
# state its meaning (doc/edge_restoration.md, "Checkpoint and resume"):
# the image of parameter_files/edge_restoration/image.prm at level 5, one
# step, checkpoint after it; resumes with another <Restoration / Eta>,
# <Restoration / Region> or <Geometry / Image file> are refused with exit
# status 2 and a message naming the parameter and both values; the eta
# allowed by <Checkpoint / Allow parameter change> resumes with a warning.
ranks="$1"; mpiexec="$2"; program="$3"; work="$4"
. "$(dirname "$0")/common.sh"
images="$(cd "$(dirname "$0")/../.." && pwd)/parameter_files/edge_restoration"
other_image="$(cd "$(dirname "$0")/.." && pwd)/bad_input/gray_alpha_disc.png"
rm -rf "$work"; mkdir -p "$work"
# base <directory> <steps> <more --set ...>
base() {
  dir="$1"; steps="$2"; shift 2
  run "$ranks" "$program" "$images/image.prm" \
    --set "Geometry/Image file=$images/scratched_ellipse.png" \
    --set "Mesh/Finest level=5" --set "Time stepping/Number of steps=$steps" \
    --set "Checkpoint/Interval=1" --set "Output/VTU interval=0" \
    --set "Output directory=$work/$dir" "$@"
}
base original 1
expect "the run that writes the checkpoint" 0 "checkpoint written after step 1"
# resume <name> <more --set ...>: step 2 in a copy of the original output
resume() {
  name="$1"; shift
  cp -r "$work/original" "$work/$name"
  base "$name" 2 --set "Checkpoint/Resume=true" "$@"
}
checkpoint="checkpoint-1/checkpoint.txt"
resume eta --set "Restoration/Eta=2"
expect "another eta" 2 \
  "Cannot resume: <Restoration / Eta> = [0-9.e-]+ in the checkpoint \(<$work/eta/$checkpoint>\), but 2 in this run.*<Checkpoint / Allow parameter change> = Restoration / Eta"
resume region --set "Restoration/Region=0.25, 0.25, 0.5, 0.5"
expect "another region" 2 \
  "Cannot resume: <Restoration / Region> = .* in the checkpoint .*, but 0.25, 0.25, 0.5, 0.5 in this run"
resume image --set "Geometry/Image file=$other_image"
expect "another image file" 2 \
  "Cannot resume: <Geometry / Image file> = $images/scratched_ellipse.png in the checkpoint .*, but $other_image in this run"
resume allowed --set "Restoration/Eta=2" \
  --set "Checkpoint/Allow parameter change=Restoration/Eta"
expect "an allowed change of eta" 0 \
  "Warning: resuming with <Restoration / Eta> = [0-9.e-]+ in the checkpoint .*, but 2 in this run \(allowed by <Checkpoint / Allow parameter change>\)"
exit $failed
