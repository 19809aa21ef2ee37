#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

namespace nurbslod::python {

// Where a long job stands: its stage ("import", "tessellate") and the faces done of the total.
// The job's threads write it; the caller's thread reads it.
class JobProgress {
public:
    // the stages in the order they run; the callback names them "import" and "tessellate"
    enum Stage : int { Import = 0, Tessellate = 1 };

    // a callback for the stage, as occ::importModel and TessellationOptions take one
    std::function<void(std::size_t, std::size_t)> stage(Stage index);

    struct Reading {
        int stage = -1;  // -1: nothing reported yet
        std::size_t done = 0, total = 0;
        bool operator==(const Reading&) const = default;
    };
    Reading read() const;

private:
    std::atomic<int> stage_{-1};
    std::atomic<std::size_t> done_{0}, total_{0};
};

// Runs `job` (pure C++, without the GIL) on a worker thread while the calling thread, which
// holds the GIL, calls `report(stage_name, done, total)` about ten times a second and once more
// when a stage ends. The callback thus runs in the caller's thread: a FreeCAD command may
// update its progress dialog and process the GUI's events there. An exception of the job is
// rethrown here; one of the callback stops the reports and is raised once the job has ended
// (the job cannot be stopped midway).
void runReportingProgress(const std::function<void(JobProgress&)>& job,
                          const pybind11::object& report);

}  // namespace nurbslod::python
