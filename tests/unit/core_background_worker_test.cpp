// core::BackgroundWorker: the thread the crowd scene's next step runs on
// beside the frame (runtime::SimulatedCrowd).
#include "tessera/core/BackgroundWorker.h"
#include "tessera/core/ParallelFor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

namespace tessera::core {
namespace {

TEST(BackgroundWorker, RunsEachTaskOffTheCallersThreadOneAtATime) {
    BackgroundWorker worker;
    EXPECT_FALSE(worker.busy());
    worker.wait(); // nothing started: returns at once
    std::vector<int> order;
    std::thread::id ran;
    for (int i = 0; i < 3; ++i)
        worker.run([&, i] {
            ran = std::this_thread::get_id();
            order.push_back(i); // one at a time: no lock needed
        });
    worker.wait();
    EXPECT_FALSE(worker.busy());
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2}));
    EXPECT_NE(ran, std::this_thread::get_id());
}

TEST(BackgroundWorker, ATaskSpreadsOverTheCoresBesideTheCallersOwnLoop) {
    // The crowd step's parallel loops beside the frame's (the LOD manager's):
    // both finish, each with every index done once.
    constexpr uint32_t kCount = 100000;
    std::vector<std::atomic<uint32_t>> mine(kCount), theirs(kCount);
    BackgroundWorker worker;
    worker.run([&] { parallelFor(kCount, 0, [&](uint32_t i) { ++theirs[i]; }); });
    parallelFor(kCount, 0, [&](uint32_t i) { ++mine[i]; });
    worker.wait();
    for (uint32_t i = 0; i < kCount; ++i) {
        ASSERT_EQ(mine[i].load(), 1u) << i;
        ASSERT_EQ(theirs[i].load(), 1u) << i;
    }
}

TEST(BackgroundWorker, ATasksExceptionReachesTheWaiterOnce) {
    BackgroundWorker worker;
    worker.run([] { throw std::runtime_error("step failed"); });
    EXPECT_THROW(worker.wait(), std::runtime_error);
    EXPECT_NO_THROW(worker.wait());
    int value = 0;
    worker.run([&] { value = 7; }); // the worker goes on after a failure
    worker.wait();
    EXPECT_EQ(value, 7);
}

TEST(BackgroundWorker, DestructionWaitsForTheTaskInFlight) {
    std::atomic<bool> finished{false};
    {
        BackgroundWorker worker;
        worker.run([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            finished = true;
        });
    }
    EXPECT_TRUE(finished.load());
}

} // namespace
} // namespace tessera::core
