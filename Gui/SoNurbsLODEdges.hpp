#pragma once

#include <Inventor/fields/SoSFNode.h>
#include <Inventor/nodes/SoShape.h>

// The B-rep edges of an SoNurbsLODShape's faces, drawn view-dependently: each face's border
// at the level the face needs for the current view (the finest cached one until a worker
// made it). FreeCAD draws its edges from one fixed tessellation, whose chords sink behind the
// exact surface when zoomed in; this node takes their place in the view provider's edge
// group (under FreeCAD's line colour and width), while FreeCAD's edge set stays there, not
// drawn, for picking.
class SoNurbsLODEdges : public SoShape {
    using inherited = SoShape;
    SO_NODE_HEADER(SoNurbsLODEdges);

public:
    static void initClass();
    SoNurbsLODEdges();

    SoSFNode shape;  // the SoNurbsLODShape whose faces' borders are drawn

    void GLRender(SoGLRenderAction* action) override;
    void rayPick(SoRayPickAction* action) override;

protected:
    ~SoNurbsLODEdges() override = default;
    void generatePrimitives(SoAction* action) override;
    void computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) override;

private:
    void render(SoGLRenderAction* action);
};
