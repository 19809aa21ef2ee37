#include "CallerThreadProgress.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace py = pybind11;

namespace nurbslod::python {

namespace {
const char* const kStageNames[] = {"import", "tessellate"};
constexpr auto kReportInterval = std::chrono::milliseconds(100);
}  // namespace

std::function<void(std::size_t, std::size_t)> JobProgress::stage(Stage index) {
    return [this, index](std::size_t done, std::size_t total) {
        // one writer at a time would need a lock; a reading torn between two updates of the
        // same stage is off by a face, which a progress display does not show
        total_.store(total, std::memory_order_relaxed);
        done_.store(done, std::memory_order_relaxed);
        stage_.store(index, std::memory_order_release);
    };
}

JobProgress::Reading JobProgress::read() const {
    Reading reading;
    reading.stage = stage_.load(std::memory_order_acquire);
    reading.done = done_.load(std::memory_order_relaxed);
    reading.total = total_.load(std::memory_order_relaxed);
    if (reading.done > reading.total) reading.done = reading.total;
    return reading;
}

void runReportingProgress(const std::function<void(JobProgress&)>& job, const py::object& report) {
    JobProgress progress;
    std::mutex mutex;
    std::condition_variable finishedChanged;
    bool finished = false;
    std::exception_ptr jobError;
    std::thread worker([&] {
        try {
            job(progress);
        } catch (...) {
            jobError = std::current_exception();
        }
        std::lock_guard lock(mutex);
        finished = true;
        finishedChanged.notify_all();
    });

    std::optional<py::error_already_set> reportError;
    JobProgress::Reading last;
    auto call = [&](const JobProgress::Reading& reading) {
        if (reportError || reading.stage < 0 || reading == last) return;
        try {
            report(kStageNames[reading.stage], reading.done, reading.total);
        } catch (py::error_already_set& error) {
            reportError.emplace(std::move(error));
        }
        last = reading;
    };
    // the last stage reported, where it ended between two reports, is reported as ended
    auto finishLastStage = [&] {
        if (last.done < last.total) call({last.stage, last.total, last.total});
    };
    bool done = false;
    while (!done) {
        {
            py::gil_scoped_release release;
            std::unique_lock lock(mutex);
            done = finishedChanged.wait_for(lock, kReportInterval, [&] { return finished; });
        }
        const JobProgress::Reading reading = progress.read();
        if (reading.stage != last.stage) {
            finishLastStage();
            // a stage that began and ended between two reports (both count the model's faces)
            for (int skipped = last.stage + 1; skipped < reading.stage; ++skipped)
                call({skipped, reading.total, reading.total});
        }
        call(reading);
    }
    finishLastStage();
    {
        py::gil_scoped_release release;
        worker.join();
    }
    if (jobError) std::rethrow_exception(jobError);
    if (reportError) throw std::move(*reportError);
}

}  // namespace nurbslod::python
