#include "SoNurbsLODShape.hpp"

#include "ViewPixelSize.hpp"

// clang-format off: Coin's GL header must come before the glue header
#include <Inventor/C/glue/gl.h>
#include <Inventor/system/gl.h>
// clang-format on
#include <Inventor/SbBox3f.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/bundles/SoMaterialBundle.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/sensors/SoTimerSensor.h>
#include <time.h>

#include <Standard_Failure.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>

SO_NODE_SOURCE(SoNurbsLODShape);

std::function<void(const std::string&)> SoNurbsLODShape::reportError;

namespace {
using Clock = std::chrono::steady_clock;
using nurbslod::gui::FaceLod;

// CPU time of the calling thread: on a loaded machine the wall time of a frame includes the
// time other processes had the core, which no budget of ours can bound.
double threadCpuMilliseconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

SbBox3f boxOf(const FaceLod& lod) {
    return {lod.boxMin[0], lod.boxMin[1], lod.boxMin[2],
            lod.boxMax[0], lod.boxMax[1], lod.boxMax[2]};
}
}  // namespace

void SoNurbsLODShape::initClass() {
    // Twice is harmless for FreeCAD (a second import of the module) but not for Coin.
    if (SoType::fromName("SoNurbsLODShape").isBad()) {
        SO_NODE_INIT_CLASS(SoNurbsLODShape, SoShape, "Shape");
    }
}

SoNurbsLODShape::SoNurbsLODShape() {
    SO_NODE_CONSTRUCTOR(SoNurbsLODShape);
    SO_NODE_ADD_FIELD(pixelError, (0.5f));
    SO_NODE_ADD_FIELD(frameBudget, (20.0f));
    SO_NODE_ADD_FIELD(normalError, (1.0f));  // degrees, as NurbsLODGui's default
    SO_NODE_ADD_FIELD(hiddenFaces, (0));
    hiddenFaces.setNum(0);
    redrawSensor_ = new SoTimerSensor(&SoNurbsLODShape::redrawCheck, this);
    redrawSensor_->setInterval(SbTime(0.03));
}

SoNurbsLODShape::~SoNurbsLODShape() {
    redrawSensor_->unschedule();
    delete redrawSensor_;
}

void SoNurbsLODShape::setModel(std::shared_ptr<const nurbslod::Model> model) {
    if (!model || model->faces.empty())
        throw std::invalid_argument("the shape has no faces to display");
    setCache(std::make_unique<nurbslod::gui::FaceLodCache>(std::move(model)));
}

void SoNurbsLODShape::setCache(std::unique_ptr<nurbslod::gui::FaceLodCache> cache) {
    if (!cache) throw std::invalid_argument("no model to display");
    cache_.reset();  // waits for the old model's workers before the new one starts
    cache_ = std::move(cache);
    shownLevel_.assign(static_cast<std::size_t>(cache_->faceCount()), -1);
    stats_ = {};
    stats_.facesFailed = static_cast<int>(cache_->failures().size());
    touch();
}

nurbslod::gui::FrameStats SoNurbsLODShape::stats() const {
    nurbslod::gui::FrameStats s = stats_;
    if (cache_) {
        s.pendingJobs = cache_->pendingJobs();
        s.workerMs = cache_->workerMilliseconds();
    }
    return s;
}

void SoNurbsLODShape::redrawCheck(void* data, SoSensor*) {
    auto* self = static_cast<SoNurbsLODShape*>(data);
    if (!self->cache_) {
        self->redrawSensor_->unschedule();
        return;
    }
    if (self->cache_->hasFinished()) {
        self->touch();  // the viewer redraws; GLRender collects the levels
    } else if (self->cache_->pendingJobs() == 0) {
        self->redrawSensor_->unschedule();
    }
}

void SoNurbsLODShape::GLRender(SoGLRenderAction* action) {
    // Nothing may escape into the viewer: FreeCAD would lose the user's unsaved work.
    try {
        render(action);
    } catch (const Standard_Failure& failure) {
        report(std::string("OpenCASCADE failed while drawing: ") + failure.GetMessageString());
    } catch (const std::exception& error) {
        report(std::string("error while drawing: ") + error.what());
    } catch (...) {
        report("unknown error while drawing");
    }
}

void SoNurbsLODShape::report(const std::string& message) {
    if (message == lastError_) return;  // once, not every frame
    lastError_ = message;
    if (!reportError) return;
    try {
        reportError(message);
    } catch (...) {  // the report itself must not take the viewer down
    }
}

void SoNurbsLODShape::render(SoGLRenderAction* action) {
    if (!cache_ || !shouldGLRender(action)) return;
    SoState* state = action->getState();
    // The picture depends on the camera: no enclosing separator may cache it.
    SoCacheElement::invalidate(state);

    const auto frameStart = Clock::now();
    const double frameCpuStart = threadCpuMilliseconds();
    // Waiting for workers may use a quarter of the budget: on a loaded machine the rendering
    // thread wakes up late (10 ms measured with the cores busy), and the budget bounds the
    // whole frame's LOD work, not only the wait.
    const auto deadline = frameStart + std::chrono::microseconds(static_cast<long long>(
                                           std::max(0.0f, frameBudget.getValue()) * 250.0f));
    const nurbslod::gui::ViewPixelSize pixelSizeAt(state);
    const double allowedPixels =
        pixelError.getValue() > 0 ? static_cast<double>(pixelError.getValue()) : 0.5;
    const double normalDegrees = normalError.getValue();
    const double normalBoundDeg = normalDegrees > 0 && normalDegrees < 90 ? normalDegrees : 0.0;

    cache_->collectFinished();
    const int faceCount = cache_->faceCount();
    std::vector<char> hidden(static_cast<std::size_t>(faceCount), 0);
    for (int k = 0; k < hiddenFaces.getNum(); ++k) {
        const int face = hiddenFaces[k] - 1;
        if (face >= 0 && face < faceCount) hidden[static_cast<std::size_t>(face)] = 1;
    }
    // Size of one pixel at each visible face, model units (or -1 for a culled face).
    std::vector<double> pixelSize(static_cast<std::size_t>(faceCount), -1);
    std::vector<int> wantedLevel(static_cast<std::size_t>(faceCount), 0);
    struct Request {
        double priority;
        int face, level;
    };
    std::vector<Request> requests;
    nurbslod::gui::FrameStats frame;
    frame.frames = stats_.frames + 1;
    frame.faceTriangles.assign(static_cast<std::size_t>(faceCount), 0);
    frame.faceNormalErrorDeg.assign(static_cast<std::size_t>(faceCount), 0.0);
    for (int f = 0; f < faceCount; ++f) {
        int level = -1;
        const FaceLod* coarsest = cache_->bestCached(f, 0, &level);
        if (!coarsest) {
            ++frame.facesFailed;
            continue;
        }
        const double pixel = pixelSizeAt.at(*coarsest);
        if (pixel < 0) {
            ++frame.facesCulled;
            continue;
        }
        pixelSize[static_cast<std::size_t>(f)] = pixel;
        // Both bounds hold at the finer of the two levels: the screen-space error (section
        // 4.1 of out-of-core-lod) and the normal error (appearance, 4.1), measured on the
        // levels made so far.
        const double screen = allowedPixels * pixel;
        const int screenLevel = cache_->levelFor(screen);
        const int wanted = cache_->normalErrorLevel(f, normalBoundDeg, screenLevel);
        if (wanted > screenLevel) ++frame.facesShadingLimited;
        wantedLevel[static_cast<std::size_t>(f)] = wanted;
        if (!cache_->hasLevel(f, wanted)) {
            // section 4.2's priority: how far the cached level is from the wanted one
            int shown = -1;
            cache_->bestCached(f, wanted, &shown);
            const double desired = std::min(screen, cache_->levelTolerance(wanted));
            requests.push_back(
                {cache_->levelTolerance(shown) / std::max(desired, 1e-300), f, wanted});
        }
        ++frame.facesVisible;
    }
    std::sort(requests.begin(), requests.end(),
              [](const Request& a, const Request& b) { return a.priority > b.priority; });
    for (const Request& r : requests) cache_->request(r.face, r.level);
    frame.selectionMs =
        std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
    // Give the workers what is left of the frame budget: a level that is quick to make is
    // shown in this frame instead of the next one.
    while (cache_->pendingJobs() > 0 && Clock::now() < deadline) {
        if (cache_->waitForFinished(deadline)) cache_->collectFinished();
    }
    cache_->collectFinished();
    for (const auto& failure : cache_->takeLevelFailures())
        report("face " + std::to_string(failure.face) + ": " + failure.reason +
               "; it keeps its finest good level");
    frame.lastFrameTessellationMs =
        std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
    frame.lastFrameTessellationCpuMs = threadCpuMilliseconds() - frameCpuStart;

    // Draw. Coin may have left a vertex buffer bound: client arrays need none.
    const cc_glglue* glue = cc_glglue_instance(action->getCacheContext());
    if (cc_glglue_has_vertex_buffer_object(glue)) {
        cc_glglue_glBindBuffer(glue, GL_ARRAY_BUFFER, 0);
        cc_glglue_glBindBuffer(glue, GL_ELEMENT_ARRAY_BUFFER, 0);
    }
    SoMaterialBundle materials(action);
    materials.sendFirst();
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    for (int f = 0; f < faceCount; ++f) {
        const double pixel = pixelSize[static_cast<std::size_t>(f)];
        if (pixel < 0 || hidden[static_cast<std::size_t>(f)]) {
            shownLevel_[static_cast<std::size_t>(f)] = -1;
            continue;
        }
        int wanted = wantedLevel[static_cast<std::size_t>(f)];
        // A level that arrived in this frame may measure over the normal bound: ask for the
        // finer one it predicts now, so the frame does not count as settled.
        const int finer = cache_->normalErrorLevel(f, normalBoundDeg, wanted);
        if (finer > wanted) {
            wanted = finer;
            cache_->request(f, wanted);
        }
        int level = -1;
        const FaceLod* lod = cache_->bestCached(f, wanted, &level);
        if (!lod) continue;
        shownLevel_[static_cast<std::size_t>(f)] = level;
        if (level < wanted) ++frame.facesWaiting;
        const double errorPx =
            pixel > 0 ? lod->tolerance / pixel : std::numeric_limits<double>::infinity();
        frame.maxScreenErrorPx = std::max(frame.maxScreenErrorPx, errorPx);
        frame.maxNormalErrorDeg = std::max(frame.maxNormalErrorDeg, lod->maxNormalErrorDeg);
        frame.faceNormalErrorDeg[static_cast<std::size_t>(f)] = lod->maxNormalErrorDeg;
        if (normalBoundDeg > 0 && lod->maxNormalErrorDeg > normalBoundDeg)
            ++frame.facesNormalErrorOver;
        frame.triangles += lod->triangleCount();
        frame.faceTriangles[static_cast<std::size_t>(f)] = lod->triangleCount();
        glVertexPointer(3, GL_FLOAT, 0, lod->positions.data());
        glNormalPointer(GL_FLOAT, 0, lod->normals.data());
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(lod->indices.size()), GL_UNSIGNED_INT,
                       lod->indices.data());
    }
    glPopClientAttrib();
    stats_ = frame;
    if (cache_->pendingJobs() > 0 || cache_->hasFinished()) scheduleRedraw();
}

void SoNurbsLODShape::scheduleRedraw() {
    if (!redrawSensor_->isScheduled()) redrawSensor_->schedule();
}

void SoNurbsLODShape::rayPick(SoRayPickAction*) {
    // Picks go to FreeCAD's face set, whose details FreeCAD maps to "FaceN".
}

void SoNurbsLODShape::getPrimitiveCount(SoGetPrimitiveCountAction* action) {
    if (!cache_ || !shouldPrimitiveCount(action)) return;
    for (int f = 0; f < cache_->faceCount(); ++f) {
        const int level = shownLevel_[static_cast<std::size_t>(f)];
        if (const FaceLod* lod = cache_->bestCached(f, std::max(level, 0), nullptr))
            action->addNumTriangles(static_cast<int>(lod->triangleCount()));
    }
}

void SoNurbsLODShape::generatePrimitives(SoAction* action) {
    // The levels drawn last (level 0 before the first frame), for callback actions.
    if (!cache_) return;
    SoPrimitiveVertex vertex;
    for (int f = 0; f < cache_->faceCount(); ++f) {
        const int level = shownLevel_[static_cast<std::size_t>(f)];
        const FaceLod* lod = cache_->bestCached(f, std::max(level, 0), nullptr);
        if (!lod) continue;
        beginShape(action, TRIANGLES);
        for (std::uint32_t index : lod->indices) {
            const float* p = &lod->positions[3 * std::size_t{index}];
            const float* n = &lod->normals[3 * std::size_t{index}];
            vertex.setPoint(SbVec3f(p[0], p[1], p[2]));
            vertex.setNormal(SbVec3f(n[0], n[1], n[2]));
            shapeVertex(&vertex);
        }
        endShape();
    }
}

void SoNurbsLODShape::computeBBox(SoAction*, SbBox3f& box, SbVec3f& center) {
    box.makeEmpty();
    if (cache_) {
        for (int f = 0; f < cache_->faceCount(); ++f)
            if (const FaceLod* lod = cache_->bestCached(f, 0, nullptr)) box.extendBy(boxOf(*lod));
    }
    if (box.isEmpty()) box.extendBy(SbVec3f(0, 0, 0));
    center = box.getCenter();
}
