#pragma once

#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "lod/FaceLod.hpp"
#include "tessellate/Model.hpp"

namespace nurbslod::gui {

// Per-face LOD caches of a model (paper out-of-core-lod, section 3.5): level k of a face is
// tessellated within coarsest / 2^k, so the error halves with each level, and levels are made
// on demand. Finer levels are made by oneTBB worker threads while the frame shows the finest
// level already cached; finished levels wait in a queue until the rendering thread collects
// them, so a frame never sees a half-made level.
//
// All members except the workers' are used from one thread (the one that renders).
// Workers run in their own arena with one thread fewer than the cores (at least one).
class FaceLodCache {
public:
    // Levels finer than this fraction of the model's size are not made: float vertex
    // positions carry about 7 digits, so a finer tessellation would draw no better.
    static constexpr double finestRelativeTolerance = 2e-6;
    // Level 0, the coarsest, which every face gets at once (section 3.5 starts the face LODs
    // at half the error of the HLOD above them; without HLODs, 1% of the model size).
    static constexpr double coarsestRelativeTolerance = 1e-2;

    struct Failure {
        int face = 0;  // 1-based, FreeCAD's shape.Faces order
        std::string reason;
    };

    // Makes level 0 of every face (in parallel, waits for it). Faces that fail are listed in
    // failures() and never drawn: FreeCAD's own display keeps showing them.
    explicit FaceLodCache(std::shared_ptr<const Model> model);
    ~FaceLodCache();  // cancels queued work, waits for the running jobs

    FaceLodCache(const FaceLodCache&) = delete;
    FaceLodCache& operator=(const FaceLodCache&) = delete;

    int faceCount() const { return static_cast<int>(faces_.size()); }
    bool failed(int face) const { return !faces_[face].failure.empty(); }
    std::vector<Failure> failures() const;
    const Model& model() const { return *model_; }
    double levelTolerance(int level) const;
    int finestLevel() const { return finestLevel_; }
    // The coarsest level whose tolerance is at most `tolerance` (finestLevel() at most).
    int levelFor(double tolerance) const;

    // The level from fromLevel on that keeps the face's drawn normals within normalErrorDeg of
    // the exact ones (paper appearance, section 4.1; InterpolatedNormalError), as far as its
    // levels made so far tell: the coarsest one from fromLevel on measured within the bound,
    // unless the finest level measured over the bound before it predicts a coarser one that is
    // not made yet. The interpolated normal's error is second order in the triangles' size,
    // i.e. proportional to the level's tolerance, so it halves per level: a level measured at
    // e > bound predicts the bound met ceil(log2(e / bound)) levels finer (at most 3 levels a
    // step). The level asked for is made, measured and the rule applied again, so the choice
    // rests on measured levels, not on the prediction. A face whose error does not halve over
    // 6 levels (64 times the tolerance) is refined no further: its error is not where the
    // tessellator refines (stats count it over the bound). fromLevel when the bound is off
    // (normalErrorDeg <= 0) or the face failed.
    int normalErrorLevel(int face, double normalErrorDeg, int fromLevel) const;

    // The level to draw for a face that wants `wanted`: the coarsest cached level at least as
    // fine, else the finest cached one (coarser than wanted). Null for a failed face.
    const FaceLod* bestCached(int face, int wanted, int* level) const;
    bool hasLevel(int face, int level) const;
    // Asks a worker for the level unless the face has a job already or failed at it.
    void request(int face, int level);

    // Moves finished levels into the caches; returns how many arrived.
    int collectFinished();
    // Finer levels that failed since the last call (the face keeps its finest good level).
    std::vector<Failure> takeLevelFailures();
    // Waits until every pending job finished or the deadline passed; true when levels wait
    // to be collected.
    bool waitForFinished(std::chrono::steady_clock::time_point deadline);
    int pendingJobs() const { return pending_.load(); }
    bool hasFinished() const;
    double workerMilliseconds() const { return workerMicroseconds_.load() / 1000.0; }

    // An edit: the face gets a new surface and loops (from `replacement`, a one-face model);
    // its cached levels are dropped and `level` is made at once, in this thread, so the frame
    // after the edit shows it. Returns the milliseconds that took, or throws
    // std::runtime_error with the reason when the new face cannot be tessellated (the old
    // levels are then kept).
    double replaceFace(int face, const Model& replacement, int level);
    // An edit that keeps the face's loops: pole (i, j) (0-based) of its surface moves to
    // `position` (its weight kept). Otherwise like replaceFace; throws std::out_of_range for
    // a pole the surface does not have.
    double movePole(int face, int i, int j, const Point3& position, int level);

private:
    double installFace(int face, std::shared_ptr<Model> edited, int level,
                       std::chrono::steady_clock::time_point start);
    struct FaceState {
        std::map<int, std::shared_ptr<const FaceLod>> levels;
        int pendingLevel = -1;
        int failedLevel = -1;  // the coarsest level that failed; finer ones are not tried
        std::string failure;   // level 0 failed: the face is not drawn
        int generation = 0;    // bumped by an edit: jobs of an older surface are dropped
    };
    struct Finished {
        int face, level, generation;
        FaceLodResult result;
    };

    std::shared_ptr<const Model> model_;
    std::vector<FaceState> faces_;
    int finestLevel_ = 0;

    mutable std::mutex finishedMutex_;
    std::condition_variable finishedChanged_;
    std::vector<Finished> finished_;
    std::vector<Failure> levelFailures_;  // rendering thread only
    std::atomic<int> pending_{0};
    std::atomic<bool> cancelled_{false};
    std::atomic<long long> workerMicroseconds_{0};
    // The workers' own arena, one thread short of the cores: the rendering thread keeps a
    // core to itself, so a frame is not slowed down by the levels it asked for.
    tbb::task_arena workers_;
};

}  // namespace nurbslod::gui
