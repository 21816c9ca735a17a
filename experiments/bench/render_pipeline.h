#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Frames per second of the full video pipeline (scene update, overlays, OSMesa render,
// read-back, text overlay, H.264 encoding through ffmpeg on its own thread and process)
// against bare mjv_updateScene + mjr_render + mjr_readPixels on the same model at the same
// resolution. Target: the pipeline keeps >= 70% of the bare rate.
Section benchRenderPipeline(bool quick);

}  // namespace cosim::bench
