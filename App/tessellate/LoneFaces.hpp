#pragma once

#include <cstddef>
#include <vector>

#include "tessellate/Mesh.hpp"
#include "tessellate/Model.hpp"

namespace nurbslod {

// The lone faces of the model, 0-based, in order. A lone face: every edge of it is used by it
// alone and every B-rep vertex of those edges by its edges alone (a sheet of its own, an open
// tube), so that it can be tessellated apart from the rest of the model with the same result at
// its boundary. Here also: at least one edge is free (used once, not degenerated), every free
// edge is exact (tolerance at most `exactEdgeTolerance`), and its trimmed region is its whole
// frame box (regionIsTheBox: every curve straight along one of the box's sides).
std::vector<int> loneBoxFaces(const Model& model, double exactEdgeTolerance);

// The model of face `face` (0-based) alone: the face (as face 1), its edges and their vertices,
// renumbered.
Model loneFaceModel(const Model& model, int face);

// The open edges of face `face` (1-based) in the mesh: the sides of its triangles that no other
// of its triangles has.
std::size_t faceOpenEdges(const Mesh& mesh, int face);

// The open edges of the whole mesh (the sides of its triangles that no other triangle has) by
// the face of their triangle (index face - 1; `faces` in all).
std::vector<std::size_t> meshOpenEdgesByFace(const Mesh& mesh, std::size_t faces);

// Replaces the triangles of face `face` (1-based) with the triangles of `alone`, a mesh of that
// face only, where the face's first triangle was; the positions and normals no triangle uses
// any longer go.
void replaceFaceTriangles(Mesh& mesh, int face, const Mesh& alone);

}  // namespace nurbslod
