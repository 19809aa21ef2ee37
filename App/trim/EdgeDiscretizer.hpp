#pragma once

#include <functional>
#include <vector>

#include "trim/CurveOnSurface.hpp"

namespace nurbslod {

// One cache of evaluated points per use, in order: what the functions below take as `points`.
std::vector<CurvePoints> curvePointsOf(const std::vector<CurveOnSurface>& uses);

// Whether the piece [s0, s1] of an edge is one chord for discretizeEdge: every use's curve
// within `approximation` of its chord there (chordBound, its interpolation trusted).
bool chordSettles(std::vector<CurvePoints>& uses, double s0, double s1, double approximation);

// Discretises one B-rep edge for all the faces that use it (its curves on their surfaces), in
// the edge's normalised parameter s in [0, 1], so that every face's 3D curve stays within
// `approximation` of its chords (midpoint subdivision under the chord bound, paper section 5.1)
// and then the polyline is simplified with a Hausdorff distance of `simplification` (the
// paper's (1 - gamma) share). Returns the increasing parameters, 0 and 1 included.
// `halving`, where given, says where a piece [s0, s1] that is not flat enough is split (by
// default in the middle of s): ModelTessellator puts the points on a face's kd-tree lines.
using PieceHalving = std::function<double(double s0, double s1)>;
// `points`, where given (curvePointsOf(uses)), are the uses' points already evaluated (one per use,
// in order): an edge discretised more than one way, then merged, evaluates each point once.
std::vector<double> discretizeEdge(const std::vector<CurveOnSurface>& uses, double approximation,
                                   double simplification, const PieceHalving& halving = {},
                                   std::vector<CurvePoints>* points = nullptr);

// The same bound (`approximation` + `simplification` from every face's curve) reached with the
// longest chords it allows: from each point the chord is stretched (doubling, then bisection)
// as far as the bound holds. Fewer points than midpoint subdivision and simplification, whose
// chords stop anywhere between a quarter and all of the bound; but the chords are longer in
// (u, v) too, and the kd-tree then cuts more cells along them, so it pays where the number of
// boundary segments itself matters: a free edge, whose every segment is an open edge of the mesh.
std::vector<double> discretizeEdgeByLongestChords(const std::vector<CurveOnSurface>& uses,
                                                  double approximation, double simplification);

// The points of `params` (increasing, 0 and 1 included) that a greedy walk keeps: from each
// kept point, the farthest later one whose chord is within the same bound as above
// (`approximation` + `simplification`, every face's curve). Fewer points than the midpoint
// subdivision and simplification left, at about their cost (one chord bound per point), and
// only points they chose.
std::vector<double> mergeChords(const std::vector<CurveOnSurface>& uses,
                                const std::vector<double>& params, double approximation,
                                double simplification, std::vector<CurvePoints>* points = nullptr);

}  // namespace nurbslod
