#include "tessera/core/BackgroundWorker.h"

#include <utility>

namespace tessera::core {

BackgroundWorker::~BackgroundWorker() {
    {
        std::unique_lock lock(mMutex);
        mDone.wait(lock, [this] { return !mPending; });
        mQuit = true;
    }
    mWake.notify_one();
    if (mThread.joinable()) mThread.join();
}

void BackgroundWorker::run(std::function<void()> task) {
    wait();
    {
        std::lock_guard lock(mMutex);
        mTask = std::move(task);
        mPending = true;
    }
    // Started lazily: a scene that never runs ahead holds no thread.
    if (!mThread.joinable()) mThread = std::thread([this] { loop(); });
    mWake.notify_one();
}

void BackgroundWorker::wait() {
    std::exception_ptr failure;
    {
        std::unique_lock lock(mMutex);
        mDone.wait(lock, [this] { return !mPending; });
        failure = std::exchange(mFailure, nullptr);
    }
    if (failure) std::rethrow_exception(failure);
}

bool BackgroundWorker::busy() const {
    std::lock_guard lock(mMutex);
    return mPending;
}

void BackgroundWorker::loop() {
    std::unique_lock lock(mMutex);
    for (;;) {
        mWake.wait(lock, [this] { return mQuit || (mPending && mTask); });
        if (mQuit) return;
        std::function<void()> task = std::exchange(mTask, nullptr);
        lock.unlock();
        std::exception_ptr failure;
        try {
            task();
        } catch (...) {
            failure = std::current_exception();
        }
        lock.lock();
        mFailure = failure;
        mPending = false;
        mDone.notify_all();
    }
}

} // namespace tessera::core
