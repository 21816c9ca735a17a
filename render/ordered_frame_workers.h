#pragma once
// Renders the frames of one video on several threads at once and hands them over in order.
// Software rendering (OSMesa/llvmpipe) spends much of a frame on one core (scene set-up,
// triangle binning, reading the pixels back), so whole frames in parallel use the machine
// where llvmpipe's own rasterizer threads cannot. Each worker owns an OSMesa context and a
// RunRenderer of its own (an OpenGL context is current on one thread only); every frame is a
// function of the log and its time alone, so the video is the same for any number of workers.
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "render/camera_rig.h"
#include "run/record/run_record.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

struct FrameSequence {
  CameraKind camera = CameraKind::Chase;
  int frames = 0;
  double seconds_per_frame = 0.0;  // simulated seconds between frames
  int width = 0, height = 0;
  double start_time = 0.0;  // s, the simulated time of frame 0
};

// Threads for rendering a video: all cores (at least 1).
int defaultRenderWorkers();

// Renders frame k at simulated time start_time + k * seconds_per_frame for k = 0 .. frames - 1 on
// `workers` threads, and calls deliver(frame) on the calling thread in the order of k (deliver may
// swap the buffer for another of the same size). interrupt: polled while waiting; once set, the
// workers stop and the result is the number of frames delivered so far. An exception in a
// worker (or in deliver) stops the others and is rethrown here.
int renderFramesInOrder(const Scenario& scenario, const RunRecord& record,
                        const FrameSequence& sequence, int workers,
                        const std::function<void(std::vector<std::uint8_t>&)>& deliver,
                        const std::atomic<bool>* interrupt = nullptr);

}  // namespace cosim
