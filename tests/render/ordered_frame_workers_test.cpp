// Frames rendered on several threads are the frames one renderer draws, handed over in order.
#include "render/ordered_frame_workers.h"

#include <gtest/gtest.h>

#include "render/run_renderer.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

using namespace cosim;
using namespace cosim::test;

TEST(OrderedFrameWorkers, ThreeWorkersDeliverExactlyTheSingleRendererFramesInOrder) {
  const Scenario s = renderTestScenario(160, 90);
  const WorldModel world = WorldModel::build(s);
  const RunLog log = straightFlightLog(2.0);
  const FrameSequence sequence{CameraKind::Chase, 7, 0.3, 160, 90};
  std::vector<std::vector<std::uint8_t>> expected;
  {
    const RunRecord one_record = recordOfLog(s, log, world);
    RunRenderer one(s, one_record, 160, 90);
    for (int k = 0; k < sequence.frames; ++k)
      one.render(k * sequence.seconds_per_frame, sequence.camera, expected.emplace_back());
  }
  // The frames differ from each other (the vehicle moves), so an order mix-up would show.
  ASSERT_NE(expected[0], expected[6]);
  std::vector<std::vector<std::uint8_t>> got;
  const RunRecord record = recordOfLog(s, log, world);
  const int delivered = renderFramesInOrder(
      s, record, sequence, 3, [&](std::vector<std::uint8_t>& rgb) { got.push_back(rgb); });
  EXPECT_EQ(delivered, 7);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t k = 0; k < got.size(); ++k) EXPECT_TRUE(got[k] == expected[k]) << "frame " << k;
}

TEST(OrderedFrameWorkers, InterruptStopsTheWorkersBeforeTheEnd) {
  const Scenario s = renderTestScenario(160, 90);
  const WorldModel world = WorldModel::build(s);
  const RunLog log = straightFlightLog(2.0);
  const FrameSequence sequence{CameraKind::Top, 200, 0.01, 160, 90};
  std::atomic<bool> stop{false};
  int seen = 0;
  const RunRecord record = recordOfLog(s, log, world);
  const int delivered = renderFramesInOrder(
      s, record, sequence, 2,
      [&](std::vector<std::uint8_t>&) {
        if (++seen == 3) stop = true;
      },
      &stop);
  EXPECT_EQ(delivered, 3);
}

TEST(OrderedFrameWorkers, AnErrorInTheConsumerReachesTheCaller) {
  const Scenario s = renderTestScenario(160, 90);
  const WorldModel world = WorldModel::build(s);
  const RunLog log = straightFlightLog(1.0);
  const FrameSequence sequence{CameraKind::Top, 10, 0.1, 160, 90};
  const RunRecord record = recordOfLog(s, log, world);
  EXPECT_THROW(renderFramesInOrder(
                   s, record, sequence, 2,
                   [](std::vector<std::uint8_t>&) { throw std::runtime_error("disk full"); }),
               std::runtime_error);
}
