#pragma once

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/nodes/SoShape.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lod/FaceLodCache.hpp"

class SoTimerSensor;
class SoSensor;

namespace nurbslod::gui {

// What the last frame drew, for the macro API's stats() and the tests.
struct FrameStats {
    std::size_t triangles = 0;
    double maxScreenErrorPx = 0;  // of the drawn levels, over the visible faces
    // Measured on the drawn levels, over the visible faces: the largest angle between the
    // normal interpolated across a triangle and the exact normal there (FaceLod).
    double maxNormalErrorDeg = 0;
    double lastFrameTessellationMs = 0;     // time the frame spent on LOD work (selection, waiting)
    double lastFrameTessellationCpuMs = 0;  // the same in CPU time of the rendering thread
    double selectionMs = 0;                 // of which choosing levels and culling
    int facesVisible = 0;
    int facesCulled = 0;
    int facesFailed = 0;
    int facesWaiting = 0;  // visible faces drawn coarser than wanted, a finer level pending
    // Visible faces whose wanted level the normal error bound made finer than the screen-space
    // error alone would, and drawn faces whose measured normal error exceeds the bound.
    int facesShadingLimited = 0;
    int facesNormalErrorOver = 0;
    int pendingJobs = 0;
    double workerMs = 0;  // all background tessellation so far, summed over threads
    long long frames = 0;
    std::vector<std::size_t> faceTriangles;  // per face, drawn in the last frame (0: not drawn)
    std::vector<double> faceNormalErrorDeg;  // per face, measured on the drawn level (0: not drawn)
};

}  // namespace nurbslod::gui

// A Coin shape that draws a trimmed NURBS model view-dependently (paper out-of-core-lod,
// section 4.1): per frame, each face inside the view frustum gets
//   epsilon_desired = pixelError * (world size of one pixel at the face's nearest point),
// which for a perspective camera is 2 * pixelError * d_viewer * tan(fov_y / 2) / h_window, the
// paper's formula for pixelError = 0.5. The face shows the coarsest cached level within
// epsilon_desired, or while that level is being made by a worker, the finest cached one.
//
// The frame waits for workers at most frameBudget milliseconds; what is not finished by then
// arrives later and a timer on the rendering thread schedules a redraw.
//
// Drawing uses legacy GL client arrays (glVertexPointer, glNormalPointer) so that a GLSL
// program bound before this node (an SoShaderProgram of an analysis overlay) applies to it.
// The node does not answer ray picks: the face set of FreeCAD's view provider, kept in the
// scene but not drawn, does, so pre-selection and selection of faces work as before.
class SoNurbsLODShape : public SoShape {
    using inherited = SoShape;
    SO_NODE_HEADER(SoNurbsLODShape);

public:
    static void initClass();
    SoNurbsLODShape();

    // Where the nodes report what went wrong while drawing (the Python module sends it to
    // FreeCAD's report view); called in the rendering thread. Empty: not reported.
    static std::function<void(const std::string&)> reportError;

    SoSFFloat pixelError;   // allowed screen-space error in pixels (0.5)
    SoSFFloat frameBudget;  // milliseconds a frame may spend on LOD work (20)
    // Largest angle in degrees between the drawn (interpolated) and the exact normals (paper
    // appearance, section 4.1): each face's level is also one whose measured normal error is
    // within it (FaceLodCache::normalErrorLevel). 0 (or anything outside (0, 90)) turns the
    // bound off. Default 1.
    SoSFFloat normalError;
    // 1-based faces this node does not draw: the selected and pre-selected ones, which
    // FreeCAD's face set draws highlighted (both drawn would fight in the depth buffer).
    SoMFInt32 hiddenFaces;

    // Replaces the model; throws std::invalid_argument for a model without faces.
    void setModel(std::shared_ptr<const nurbslod::Model> model);
    // Takes a cache made elsewhere (a worker thread made it while FreeCAD kept drawing).
    void setCache(std::unique_ptr<nurbslod::gui::FaceLodCache> cache);
    bool hasModel() const { return cache_ != nullptr; }
    nurbslod::gui::FaceLodCache* cache() { return cache_.get(); }
    nurbslod::gui::FrameStats stats() const;
    // The level face `face` (0-based) showed in the last frame, -1 when not drawn.
    int shownLevel(int face) const {
        return face >= 0 && face < static_cast<int>(shownLevel_.size())
                   ? shownLevel_[static_cast<std::size_t>(face)]
                   : -1;
    }
    // The last error GLRender caught (it never lets one escape into the viewer).
    const std::string& lastError() const { return lastError_; }

    // Asks for a redraw as soon as a worker finished a level (the edges node asks for levels
    // too, in wireframe mode, where this node is not drawn).
    void scheduleRedraw();
    // The model's box (computeBBox, callable by the edges node).
    void getBoundingBox(SoAction* action, SbBox3f& box, SbVec3f& center) {
        computeBBox(action, box, center);
    }

    void GLRender(SoGLRenderAction* action) override;
    void rayPick(SoRayPickAction* action) override;
    void getPrimitiveCount(SoGetPrimitiveCountAction* action) override;

protected:
    ~SoNurbsLODShape() override;
    void generatePrimitives(SoAction* action) override;
    void computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) override;

private:
    void render(SoGLRenderAction* action);
    void report(const std::string& message);
    static void redrawCheck(void* data, SoSensor* sensor);

    std::unique_ptr<nurbslod::gui::FaceLodCache> cache_;
    std::vector<int> shownLevel_;  // per face, -1: not drawn
    nurbslod::gui::FrameStats stats_;
    std::string lastError_;
    SoTimerSensor* redrawSensor_ = nullptr;
};
