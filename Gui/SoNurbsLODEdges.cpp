#include "SoNurbsLODEdges.hpp"

// clang-format off: Coin's GL header must come before the glue header
#include <Inventor/C/glue/gl.h>
#include <Inventor/system/gl.h>
// clang-format on
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/bundles/SoMaterialBundle.h>
#include <Inventor/elements/SoCacheElement.h>

#include <Standard_Failure.hxx>
#include <algorithm>
#include <exception>

#include "SoNurbsLODShape.hpp"
#include "ViewPixelSize.hpp"

SO_NODE_SOURCE(SoNurbsLODEdges);

void SoNurbsLODEdges::initClass() {
    if (SoType::fromName("SoNurbsLODEdges").isBad()) {
        SO_NODE_INIT_CLASS(SoNurbsLODEdges, SoShape, "Shape");
    }
}

SoNurbsLODEdges::SoNurbsLODEdges() {
    SO_NODE_CONSTRUCTOR(SoNurbsLODEdges);
    SO_NODE_ADD_FIELD(shape, (nullptr));
}

void SoNurbsLODEdges::GLRender(SoGLRenderAction* action) {
    // Nothing may escape into the viewer (see SoNurbsLODShape::GLRender).
    try {
        render(action);
    } catch (const Standard_Failure&) {
    } catch (const std::exception&) {
    } catch (...) {
    }
}

void SoNurbsLODEdges::render(SoGLRenderAction* action) {
    auto* faces = static_cast<SoNurbsLODShape*>(shape.getValue());
    if (!faces || !faces->isOfType(SoNurbsLODShape::getClassTypeId()) || !faces->hasModel() ||
        !shouldGLRender(action))
        return;
    SoState* state = action->getState();
    SoCacheElement::invalidate(state);
    nurbslod::gui::FaceLodCache& cache = *faces->cache();
    const nurbslod::gui::ViewPixelSize pixelSizeAt(state);
    const double allowedPixels =
        faces->pixelError.getValue() > 0 ? static_cast<double>(faces->pixelError.getValue()) : 0.5;

    const cc_glglue* glue = cc_glglue_instance(action->getCacheContext());
    if (cc_glglue_has_vertex_buffer_object(glue)) {
        cc_glglue_glBindBuffer(glue, GL_ARRAY_BUFFER, 0);
        cc_glglue_glBindBuffer(glue, GL_ELEMENT_ARRAY_BUFFER, 0);
    }
    SoMaterialBundle materials(action);
    materials.sendFirst();  // FreeCAD's line colour; its draw style set the line width
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_LIGHTING);  // lines in their plain colour, as FreeCAD draws its edges
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    bool wantsFiner = false;
    for (int f = 0; f < cache.faceCount(); ++f) {
        const nurbslod::gui::FaceLod* coarsest = cache.bestCached(f, 0, nullptr);
        if (!coarsest) continue;
        const double pixel = pixelSizeAt.at(*coarsest);
        if (pixel < 0) continue;
        const int wanted = cache.levelFor(allowedPixels * pixel);
        int level = -1;
        const nurbslod::gui::FaceLod* lod = cache.bestCached(f, wanted, &level);
        if (level < wanted) {
            cache.request(f, wanted);  // in wireframe mode the faces' node does not ask
            wantsFiner = true;
        }
        if (lod->borderLines.empty()) continue;
        glVertexPointer(3, GL_FLOAT, 0, lod->positions.data());
        glDrawElements(GL_LINES, static_cast<GLsizei>(lod->borderLines.size()), GL_UNSIGNED_INT,
                       lod->borderLines.data());
    }
    glPopClientAttrib();
    glPopAttrib();
    if (wantsFiner) faces->scheduleRedraw();
}

void SoNurbsLODEdges::rayPick(SoRayPickAction*) {
    // Picks go to FreeCAD's edge set, whose details FreeCAD maps to "EdgeN".
}

void SoNurbsLODEdges::generatePrimitives(SoAction*) {
    // Lines only for drawing: callback actions see FreeCAD's edge set.
}

void SoNurbsLODEdges::computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) {
    auto* faces = static_cast<SoNurbsLODShape*>(shape.getValue());
    box.makeEmpty();
    if (faces && faces->isOfType(SoNurbsLODShape::getClassTypeId())) {
        faces->getBoundingBox(action, box, center);
        return;
    }
    box.extendBy(SbVec3f(0, 0, 0));
    center = box.getCenter();
}
