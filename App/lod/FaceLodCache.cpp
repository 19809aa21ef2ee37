#include "lod/FaceLodCache.hpp"

#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "tessellate/ModelOrigin.hpp"

namespace nurbslod::gui {

namespace {
using Clock = std::chrono::steady_clock;
}

namespace {

// An edit may put a face's poles at most this many model diagonals from the middle of the
// face's poles before the edit. The levels' tolerances are fractions of the model's diagonal:
// a pole of a sphere of radius 10 moved to x = 1e6 asked for a face that size at a tolerance
// of 0.35, which the edit's own level (made in the GUI thread) tessellated for more than a
// minute (1e4 away: 1 s).
constexpr double kEditReach = 100;

// The middle of the surface's control net.
Point3 middleOfPoles(const BSplineSurface& surface) {
    const auto [low, high] = surface.controlNetBox();
    return 0.5 * (low + high);
}

// Throws std::invalid_argument where `pole` lies farther than kEditReach diagonals from
// `middle`.
void requireWithinReach(const Point3& pole, const Point3& middle, double diagonal, int face) {
    const double distance = (pole - middle).norm();
    if (distance <= kEditReach * diagonal) return;
    std::ostringstream message;
    message << std::setprecision(3) << "face " << face + 1 << ": a pole would lie " << distance
            << " from the face, more than " << kEditReach << " times the model's size (" << diagonal
            << ")";
    throw std::invalid_argument(message.str());
}

int workerThreads() {
    return std::max(1, tbb::info::default_concurrency() - 1);
}
}  // namespace

FaceLodCache::FaceLodCache(std::shared_ptr<const Model> model)
    : model_(std::move(model)), faces_(model_->faces.size()), workers_(workerThreads(), 0) {
    if (!(std::isfinite(model_->boundingBoxDiagonal) && model_->boundingBoxDiagonal > 0))
        throw std::invalid_argument("the model has an empty or invalid bounding box");
    finestLevel_ =
        static_cast<int>(std::ceil(std::log2(coarsestRelativeTolerance / finestRelativeTolerance)));
    const double tolerance = levelTolerance(0);
    tbb::parallel_for(0, faceCount(), [&](int f) {
        FaceState& state = faces_[f];
        if (!model_->faces[f].error.empty()) {
            state.failure = model_->faces[f].error;
            return;
        }
        FaceLodResult result = tessellateFaceLod(*model_, f, tolerance);
        if (!result.lod) {
            state.failure = result.failure;
            return;
        }
        state.levels[0] = std::move(result.lod);
    });
}

FaceLodCache::~FaceLodCache() {
    // Queued jobs see the flag and return at once; a running one finishes its face.
    cancelled_ = true;
    std::unique_lock lock(finishedMutex_);
    finishedChanged_.wait(lock, [this] { return pending_.load() == 0; });
}

std::vector<FaceLodCache::Failure> FaceLodCache::failures() const {
    std::vector<Failure> list;
    for (int f = 0; f < faceCount(); ++f)
        if (failed(f)) list.push_back({f + 1, faces_[f].failure});
    return list;
}

double FaceLodCache::levelTolerance(int level) const {
    return coarsestRelativeTolerance * model_->boundingBoxDiagonal * std::ldexp(1.0, -level);
}

int FaceLodCache::levelFor(double tolerance) const {
    if (!(tolerance > 0)) return finestLevel_;
    const double ratio = levelTolerance(0) / tolerance;
    if (ratio <= 1) return 0;
    // smallest k with levelTolerance(k) <= tolerance; the epsilon keeps an exact power of two
    // from stepping one level too fine through rounding
    const int level = static_cast<int>(std::ceil(std::log2(ratio) - 1e-9));
    return std::clamp(level, 0, finestLevel_);
}

namespace {
// Over this many levels (a tolerance 64 times smaller) a face's normal error must at least halve,
// or the face is refined no further. Its mesh can stay the same over a few levels (a kd-tree cell
// that meets them all: 4 levels at 2.7 degrees on a face of trj7 before it halves), so fewer
// levels would stop faces that then converge.
constexpr int stagnantLevels = 6;
// The most levels one step of the rule goes finer (8 times the triangles): where the error does
// not follow the prediction, a few steps find out before the face costs many triangles.
constexpr int largestStep = 3;
}  // namespace

int FaceLodCache::normalErrorLevel(int face, double normalErrorDeg, int fromLevel) const {
    const FaceState& state = faces_[face];
    fromLevel = std::clamp(fromLevel, 0, finestLevel_);
    if (!(normalErrorDeg > 0) || !state.failure.empty() || state.levels.empty()) return fromLevel;
    // Coarse to fine: the coarsest level from fromLevel on within the bound, the finest level
    // coarser than that over the bound, and the coarsest level over the bound.
    int meeting = -1;
    int over = -1, firstOver = -1;
    double overDeg = 0, firstOverDeg = 0;
    for (const auto& [level, lod] : state.levels) {
        if (lod->maxNormalErrorDeg <= normalErrorDeg) {
            if (level >= fromLevel) {
                meeting = level;
                break;
            }
            continue;
        }
        if (firstOver < 0) firstOver = level, firstOverDeg = lod->maxNormalErrorDeg;
        over = level, overDeg = lod->maxNormalErrorDeg;
    }
    if (over < 0) return std::max(fromLevel, meeting);
    // a level that failed to tessellate caps the finest there is
    const int finest = state.failedLevel >= 0
                           ? std::max(0, std::min(finestLevel_, state.failedLevel - 1))
                           : finestLevel_;
    int wanted;
    if (over - firstOver >= stagnantLevels && overDeg > 0.5 * firstOverDeg) {
        wanted = over;  // not halving: finer levels would cost triangles, not error
    } else {
        const int step = static_cast<int>(std::ceil(std::log2(overDeg / normalErrorDeg)));
        wanted = over + std::clamp(step, 1, largestStep);
        if (meeting >= 0) wanted = std::min(meeting, wanted);
    }
    return std::clamp(wanted, fromLevel, std::max(fromLevel, finest));
}

const FaceLod* FaceLodCache::bestCached(int face, int wanted, int* level) const {
    const FaceState& state = faces_[face];
    if (!state.failure.empty() || state.levels.empty()) return nullptr;
    auto it = state.levels.lower_bound(wanted);
    if (it == state.levels.end()) --it;  // none fine enough yet: the finest there is
    if (level) *level = it->first;
    return it->second.get();
}

bool FaceLodCache::hasLevel(int face, int level) const {
    return faces_[face].levels.count(level) != 0;
}

void FaceLodCache::request(int face, int level) {
    FaceState& state = faces_[face];
    if (!state.failure.empty() || state.pendingLevel >= 0 || state.levels.count(level)) return;
    if (state.failedLevel >= 0 && level >= state.failedLevel) return;
    state.pendingLevel = level;
    ++pending_;
    const int generation = state.generation;
    const double tolerance = levelTolerance(level);
    std::shared_ptr<const Model> model = model_;
    workers_.enqueue([this, model, face, level, generation, tolerance] {
        Finished finished{face, level, generation, {}};
        if (cancelled_) {
            finished.result.failure = "cancelled";
        } else {
            const auto start = Clock::now();
            finished.result = tessellateFaceLod(*model, face, tolerance);
            workerMicroseconds_ +=
                std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start).count();
        }
        // notified under the lock: the destructor may free the condition variable as soon as
        // it sees pending_ reach 0. Only the last job wakes the waiting frame: a wake-up per
        // job costs the rendering thread a trip through the scheduler each.
        std::lock_guard lock(finishedMutex_);
        finished_.push_back(std::move(finished));
        if (--pending_ == 0) finishedChanged_.notify_all();
    });
}

int FaceLodCache::collectFinished() {
    std::vector<Finished> arrived;
    {
        std::lock_guard lock(finishedMutex_);
        arrived.swap(finished_);
    }
    int count = 0;
    for (Finished& finished : arrived) {
        FaceState& state = faces_[finished.face];
        if (finished.generation != state.generation) continue;  // made for an edited surface
        state.pendingLevel = -1;
        if (finished.result.lod) {
            state.levels[finished.level] = std::move(finished.result.lod);
            ++count;
        } else if (finished.result.failure != "cancelled") {
            // A finer level that fails (a kd-tree depth limit, a sloppy loop) leaves the face
            // at the finest level that worked: it is still drawn, and not asked for again.
            state.failedLevel = state.failedLevel < 0 ? finished.level
                                                      : std::min(state.failedLevel, finished.level);
            levelFailures_.push_back(
                {finished.face + 1, "level " + std::to_string(finished.level) +
                                        " failed: " + finished.result.failure});
        }
    }
    return count;
}

std::vector<FaceLodCache::Failure> FaceLodCache::takeLevelFailures() {
    std::vector<Failure> taken;
    taken.swap(levelFailures_);
    return taken;
}

bool FaceLodCache::waitForFinished(Clock::time_point deadline) {
    std::unique_lock lock(finishedMutex_);
    if (!finished_.empty()) return true;
    if (pending_.load() == 0) return false;
    finishedChanged_.wait_until(lock, deadline, [this] { return pending_.load() == 0; });
    return !finished_.empty();
}

bool FaceLodCache::hasFinished() const {
    std::lock_guard lock(finishedMutex_);
    return !finished_.empty();
}

double FaceLodCache::replaceFace(int face, const Model& replacement, int level) {
    if (face < 0 || face >= faceCount())
        throw std::out_of_range("no face " + std::to_string(face + 1) + " in the model");
    if (replacement.faces.size() != 1)
        throw std::invalid_argument("the replacement must be exactly one face");
    const auto start = Clock::now();
    // The edited model: a copy that shares nothing with jobs still running on the old one.
    auto edited = std::make_shared<Model>(*model_);
    // its coordinates start where the model's do (an import may have moved either)
    const Model placed = withOrigin(replacement, model_->origin);
    const int edgeBase = static_cast<int>(edited->edges.size());
    const int vertexBase = static_cast<int>(edited->vertices.size());
    for (ModelEdge edge : placed.edges) {
        if (edge.firstVertex >= 0) edge.firstVertex += vertexBase;
        if (edge.lastVertex >= 0) edge.lastVertex += vertexBase;
        edited->edges.push_back(edge);
    }
    edited->vertices.insert(edited->vertices.end(), placed.vertices.begin(), placed.vertices.end());
    TrimmedSurface surface = placed.faces.front();
    const Point3 middle = middleOfPoles(model_->faces[face].surface);
    for (const HomogeneousPoint3& pole : surface.surface.poles())
        requireWithinReach(projectHomogeneous(pole), middle, model_->boundingBoxDiagonal, face);
    surface.faceIndex = face + 1;
    for (TrimLoop& loop : surface.loops)
        for (TrimCurve& curve : loop.curves)
            if (curve.edge >= 0) curve.edge += edgeBase;
    edited->faces[face] = std::move(surface);
    return installFace(face, std::move(edited), level, start);
}

double FaceLodCache::movePole(int face, int i, int j, const Point3& position, int level) {
    if (face < 0 || face >= faceCount())
        throw std::out_of_range("no face " + std::to_string(face + 1) + " in the model");
    const BSplineSurface& surface = model_->faces[face].surface;
    if (i < 0 || j < 0 || i >= surface.countU() || j >= surface.countV())
        throw std::out_of_range("face " + std::to_string(face + 1) + " has poles (1.." +
                                std::to_string(surface.countU()) + ", 1.." +
                                std::to_string(surface.countV()) + "), not (" +
                                std::to_string(i + 1) + ", " + std::to_string(j + 1) + ")");
    if (!position.allFinite())
        throw std::invalid_argument("face " + std::to_string(face + 1) +
                                    ": the pole position is not finite");
    requireWithinReach(position - model_->origin, middleOfPoles(surface),
                       model_->boundingBoxDiagonal, face);
    const auto start = Clock::now();
    auto edited = std::make_shared<Model>(*model_);
    HomogeneousPoint3& pole = edited->faces[face].surface.pole(i, j);
    const double weight = pole.w();
    // P^w = (w x, w y, w z, w), NURBS Book 4.15, in the model's coordinates (Model::origin)
    pole.head<3>() = weight * (position - edited->origin);
    return installFace(face, std::move(edited), level, start);
}

double FaceLodCache::installFace(int face, std::shared_ptr<Model> edited, int level,
                                 Clock::time_point start) {
    FaceLodResult result = tessellateFaceLod(*edited, face, levelTolerance(level));
    if (!result.lod)
        throw std::runtime_error("face " + std::to_string(face + 1) + ": " + result.failure);
    model_ = std::move(edited);
    FaceState& state = faces_[face];
    ++state.generation;
    state.levels.clear();
    state.levels[level] = std::move(result.lod);
    state.failure.clear();
    state.failedLevel = -1;
    if (state.pendingLevel >= 0) {
        state.pendingLevel = -1;  // its result will carry the old generation and be dropped
    }
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace nurbslod::gui
