#pragma once
/// @file BackgroundWorker.h
/// One thread that runs one task at a time beside the caller: the crowd
/// scene's next simulation step runs on it while the frame is drawn
/// (runtime::SimulatedCrowd). A task may itself spread over the cores with
/// core::parallelFor; it does so in its own oneTBB arena (the worker is an
/// application thread to oneTBB), so the caller's parallel loops never pick
/// up the task and wait on it inside theirs.

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace tessera::core {

class BackgroundWorker {
public:
    BackgroundWorker() = default;
    /// Waits for the task in flight, if any, then ends the thread.
    ~BackgroundWorker();
    BackgroundWorker(const BackgroundWorker&) = delete;
    BackgroundWorker& operator=(const BackgroundWorker&) = delete;

    /// Starts `task` on the worker thread (created on first use) and returns
    /// at once. A task still in flight is waited for first: one at a time.
    void run(std::function<void()> task);
    /// Returns once no task is in flight. An exception the task threw is
    /// rethrown here, once.
    void wait();
    /// Whether a task was started and wait() has not yet returned for it.
    bool busy() const;

private:
    void loop();

    mutable std::mutex mMutex;
    std::condition_variable mWake; ///< a task to run, or the end
    std::condition_variable mDone; ///< the task finished
    std::function<void()> mTask;
    std::exception_ptr mFailure;
    bool mPending = false; ///< started and not yet finished
    bool mQuit = false;
    std::thread mThread;
};

} // namespace tessera::core
