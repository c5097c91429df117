# Sourced by the benchmark scripts that score a render larger than its reference: the image
# rendered at WIDTHxHEIGHT, box-averaged down to 400x300 (oiiotool --resize:filter=box) and
# compared with a 400x300 reference. A WxH image averaged over 400x300 pixels estimates the same
# pixel integral as a box-filtered reference.
#
#   source tools/benchmarks/box_averaged.sh
#   box_averaged_relmse VKWATER SCENE_FILE REFERENCE WIDTH HEIGHT SCRATCH_DIR [RENDER ARGS...]
#     renders the scene and prints the image's relMSE (the RGB channels; the layers are left out of
#     the render)
#   box_averaged_image_relmse VKWATER IMAGE REFERENCE SCRATCH_DIR
#     the same for an image already rendered

box_averaged_image_relmse() {
    local vk=$1 image=$2 reference=$3 scratch=$4
    oiiotool "$image" --ch R,G,B,A --resize:filter=box 400x300 -o "$scratch/box-small.exr"
    "$vk" compare "$scratch/box-small.exr" "$reference" | awk '/^relMSE/ {print $2; exit}'
}

box_averaged_relmse() {
    local vk=$1 scene=$2 reference=$3 width=$4 height=$5 scratch=$6
    shift 6
    "$vk" render "$scene" --width "$width" --height "$height" --no-caustic-layer --no-inscatter-layer \
        --out "$scratch/box-full.exr" -q "$@"
    box_averaged_image_relmse "$vk" "$scratch/box-full.exr" "$reference" "$scratch"
}
