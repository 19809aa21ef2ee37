// evaluation_benchmark: the evaluation paper's study (evaluation.txt, Tables 1 to 5) run on this
// project's evaluators, side by side with OpenCASCADE on the same grids, in one run.
//
//   Table 5: seconds and ns per vertex of every method on every model, points only, points with
//            exact normals, points with approximated normals (area weighting), at the paper's
//            vertex counts and at 1M vertices; the peer is Geom_BSplineSurface::D0/D1 and
//            GeomAdaptor_Surface::D0/D1 (BSplSLib_Cache) on the same grid.
//   Table 2: time of the four normal weightings (goblet, torus, teapot).
//   Tables 3, 4: mean angle between approximated and exact normals, torus and goblet.
//   Table 1: angle between the approximated normals of two C1 / C2 adjacent surfaces on their
//            shared edge.
//   Beyond the paper: scattered vertices (random adaptive subdivisions), and the vertex sets
//            the tessellator really evaluates on every corpus model at relative 1e-3 and 1e-4
//            (PointSetEvaluator as FaceTessellator uses it, the former per-vertex calls,
//            OpenCASCADE's D1), with the whole tessellation's time. --tessellator-vertices
//            runs only that table.
//
// One core: times are the CPU time of the measuring thread, best of at least three runs (the
// grid evaluator's threaded row, wall time, is printed as well). --quick: small grids only, seconds
// in all, for smoke tests. --json PATH writes the figures, including for the bicubic 1M-vertex grid
// (the --quick size in quick mode) the keys occt_ns_per_vertex_normals and
// best_ns_per_vertex_normals.
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <CLI/CLI.hpp>
#include <GeomAdaptor_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../unit/OcctSurface.hpp"
#include "geometry/ApproximatedNormals.hpp"
#include "geometry/EvaluationMethods.hpp"
#include "geometry/EvaluationStudyModels.hpp"
#include "geometry/GridEvaluator.hpp"
#include "geometry/PointSetEvaluator.hpp"
#include "geometry/SurfaceNormal.hpp"
#include "occ/ModelImporter.hpp"
#include "occ/ShapeReader.hpp"
#include "tessellate/ModelTessellator.hpp"

using namespace nurbslod;

namespace {

using Clock = std::chrono::steady_clock;

// The time of one run: CPU time of the calling thread by default. The machine this runs on is
// shared (other builds), and wall time would count the time the thread waited for a core;
// thread CPU time does not (cache and memory effects of the neighbours remain). The threaded
// rows use wall time, since their work runs on other threads.
double secondsOf(const std::function<void()>& run, bool wall) {
    if (wall) {
        const auto start = Clock::now();
        run();
        return std::chrono::duration<double>(Clock::now() - start).count();
    }
    timespec a{}, b{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    run();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    return double(b.tv_sec - a.tv_sec) + 1e-9 * double(b.tv_nsec - a.tv_nsec);
}

// Best of several runs: at least `minRuns`, more while the total stays under `budget` seconds.
double bestSeconds(const std::function<void()>& run, int minRuns, double budget,
                   bool wall = false) {
    double best = 1e300, total = 0;
    for (int k = 0; k < 50; ++k) {
        const double seconds = secondsOf(run, wall);
        best = std::min(best, seconds);
        total += seconds;
        if (k + 1 >= minRuns && total > budget) break;
        if (seconds > 2.0) break;  // one run of a slow method at 1M vertices says enough
    }
    return best;
}

std::vector<double> uniform(double a, double b, int n) {
    std::vector<double> out(n);
    for (int k = 0; k < n; ++k) out[k] = a + (b - a) * k / (n - 1);
    return out;
}

// A model's surfaces with the grid each gets: `vertices` spread evenly, n x n per surface.
struct GridJob {
    const BSplineSurface* surface;
    Handle(Geom_BSplineSurface) occt;
    std::vector<double> us, vs;
};

struct Benchmark {
    std::string name;
    std::vector<BSplineSurface> surfaces;
    std::vector<Handle(Geom_BSplineSurface)> occt;
};

std::vector<GridJob> gridJobs(const Benchmark& b, long vertices, long& actual) {
    const int perSide =
        std::max(3, static_cast<int>(std::lround(std::sqrt(double(vertices) / b.surfaces.size()))));
    std::vector<GridJob> jobs;
    actual = 0;
    for (size_t s = 0; s < b.surfaces.size(); ++s) {
        const auto& surface = b.surfaces[s];
        jobs.push_back({&surface, b.occt[s],
                        uniform(surface.knotsU().first(), surface.knotsU().last(), perSide),
                        uniform(surface.knotsV().first(), surface.knotsV().last(), perSide)});
        actual += static_cast<long>(perSide) * perSide;
    }
    return jobs;
}

enum class Mode { Points, ExactNormals, ApproximatedNormals };
const char* modeName(Mode m) {
    return m == Mode::Points         ? "points"
           : m == Mode::ExactNormals ? "exact normals"
                                     : "approx. normals";
}

struct Row {
    std::string model, method;
    long vertices;
    double seconds[3] = {0, 0, 0};  // per Mode
};

double gSink = 0;  // keeps the optimiser from dropping the peer's loops

// OpenCASCADE's point and unit normal (du x dv, left as it is where it vanishes) from its D1.
void occtPointAndNormal(const gp_Pnt& p, const gp_Vec& du, const gp_Vec& dv, Point3& point,
                        Vector3& normal) {
    gp_Vec n = du.Crossed(dv);
    const double m = n.Magnitude();
    if (m > 0) n /= m;
    point = Point3(p.X(), p.Y(), p.Z());
    normal = Vector3(n.X(), n.Y(), n.Z());
}

// OpenCASCADE on the same grids: D0 for points, D1 and the normalised cross product for
// normals; `adaptor` uses GeomAdaptor_Surface, whose D0/D1 go through BSplSLib_Cache.
void occtGrid(const GridJob& job, Mode mode, bool adaptor, std::vector<Point3>& points,
              std::vector<Vector3>& normals) {
    GeomAdaptor_Surface surface;
    if (adaptor) surface.Load(job.occt);
    size_t k = 0;
    for (double u : job.us)
        for (double v : job.vs) {
            gp_Pnt p;
            if (mode == Mode::Points) {
                if (adaptor)
                    surface.D0(u, v, p);
                else
                    job.occt->D0(u, v, p);
            } else {
                gp_Vec du, dv;
                if (adaptor)
                    surface.D1(u, v, p, du, dv);
                else
                    job.occt->D1(u, v, p, du, dv);
                if (mode == Mode::ExactNormals) {
                    gp_Vec n = du.Crossed(dv);
                    const double m = n.Magnitude();
                    if (m > 0) n /= m;
                    normals[k] = Vector3(n.X(), n.Y(), n.Z());
                }
            }
            points[k++] = Point3(p.X(), p.Y(), p.Z());
        }
    if (mode == Mode::ApproximatedNormals)
        approximateGridNormals(points.data(), static_cast<int>(job.us.size()),
                               static_cast<int>(job.vs.size()), NormalWeighting::Area,
                               normals.data());
    gSink += points[k / 2].x();
}

std::vector<Row> table5For(const Benchmark& b, long vertices, int threads, double budget) {
    long actual = 0;
    const auto jobs = gridJobs(b, vertices, actual);
    size_t largest = 0;
    for (const auto& j : jobs) largest = std::max(largest, j.us.size() * j.vs.size());
    std::vector<Point3> points(largest);
    std::vector<Vector3> normals(largest);
    std::vector<Row> rows;
    const int minRuns = 3;
    // the study's methods, each built once per surface (conversions are not timed, section 2.2)
    std::vector<std::vector<std::unique_ptr<SurfaceEvaluationMethod>>> methods;
    for (const auto& j : jobs) methods.push_back(makeEvaluationMethods(*j.surface));
    for (size_t m = 0; m < methods.front().size(); ++m) {
        Row row{b.name, methods.front()[m]->name(), actual};
        for (Mode mode : {Mode::Points, Mode::ExactNormals, Mode::ApproximatedNormals}) {
            row.seconds[int(mode)] = bestSeconds(
                [&] {
                    for (size_t s = 0; s < jobs.size(); ++s) {
                        const auto& j = jobs[s];
                        methods[s][m]->evaluate(
                            j.us, j.vs, points.data(),
                            mode == Mode::ExactNormals ? normals.data() : nullptr);
                        if (mode == Mode::ApproximatedNormals)
                            approximateGridNormals(points.data(), int(j.us.size()),
                                                   int(j.vs.size()), NormalWeighting::Area,
                                                   normals.data());
                    }
                },
                minRuns, budget);
        }
        rows.push_back(row);
    }
    if (threads > 1) {
        std::vector<GridEvaluator> evaluators;
        for (const auto& j : jobs) evaluators.emplace_back(*j.surface);
        Row row{b.name, "grid evaluator AVX2, " + std::to_string(threads) + " threads", actual};
        for (Mode mode : {Mode::Points, Mode::ExactNormals, Mode::ApproximatedNormals})
            row.seconds[int(mode)] = bestSeconds(
                [&] {
                    for (size_t s = 0; s < jobs.size(); ++s) {
                        const auto& j = jobs[s];
                        evaluators[s].evaluate(
                            j.us, j.vs, points.data(),
                            mode == Mode::ExactNormals ? normals.data() : nullptr, threads);
                        if (mode == Mode::ApproximatedNormals)
                            approximateGridNormals(points.data(), int(j.us.size()),
                                                   int(j.vs.size()), NormalWeighting::Area,
                                                   normals.data());
                    }
                },
                minRuns, budget, /*wall=*/true);
        rows.push_back(row);
    }
    for (bool adaptor : {false, true}) {
        Row row{b.name,
                adaptor ? "OCCT GeomAdaptor (BSplSLib cache)" : "OCCT Geom_BSplineSurface D0/D1",
                actual};
        for (Mode mode : {Mode::Points, Mode::ExactNormals, Mode::ApproximatedNormals})
            row.seconds[int(mode)] = bestSeconds(
                [&] {
                    for (const auto& j : jobs) occtGrid(j, mode, adaptor, points, normals);
                },
                minRuns, budget);
        rows.push_back(row);
    }
    return rows;
}

void printTable5(const std::vector<Row>& rows) {
    std::printf("\n%-22s %-38s %9s | %10s %8s | %10s %8s | %10s %8s | %8s\n", "model", "method",
                "vertices", "points s", "ns/vtx", "exact n. s", "ns/vtx", "approx. s", "ns/vtx",
                "vs OCCT");
    // the faster OpenCASCADE path with exact normals, per model and size, for the ratio column
    std::map<std::pair<std::string, long>, double> occt;
    for (const auto& r : rows)
        if (r.method.rfind("OCCT", 0) == 0) {
            auto& best = occt[{r.model, r.vertices}];
            best = best == 0 ? r.seconds[1] : std::min(best, r.seconds[1]);
        }
    std::string lastModel;
    for (const auto& r : rows) {
        if (r.model != lastModel && !lastModel.empty()) std::printf("\n");
        lastModel = r.model;
        const double n = double(r.vertices);
        std::printf("%-22s %-38s %9ld | %10.5f %8.1f | %10.5f %8.1f | %10.5f %8.1f | %7.1fx\n",
                    r.model.c_str(), r.method.c_str(), r.vertices, r.seconds[0],
                    r.seconds[0] * 1e9 / n, r.seconds[1], r.seconds[1] * 1e9 / n, r.seconds[2],
                    r.seconds[2] * 1e9 / n, occt[{r.model, r.vertices}] / r.seconds[1]);
    }
}

double angleDegrees(const Vector3& a, const Vector3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
}

const NormalWeighting kWeightings[] = {NormalWeighting::Uniform, NormalWeighting::Area,
                                       NormalWeighting::InverseArea, NormalWeighting::Angle};

// Tables 3 and 4: mean deviation of the approximated normals from the exact ones.
std::vector<std::vector<double>> deviationTable(const BSplineSurface& surface,
                                                const std::vector<long>& counts) {
    std::vector<std::vector<double>> out;
    const GridEvaluator evaluator(surface);
    for (long count : counts) {
        const int n = static_cast<int>(std::lround(std::sqrt(double(count))));
        const auto us = uniform(surface.knotsU().first(), surface.knotsU().last(), n);
        const auto vs = uniform(surface.knotsV().first(), surface.knotsV().last(), n);
        std::vector<Point3> points;
        std::vector<Vector3> exact, approximated(size_t(n) * n);
        evaluator.evaluate(us, vs, points, &exact);
        std::vector<double> row;
        for (NormalWeighting w : kWeightings) {
            approximateGridNormals(points.data(), n, n, w, approximated.data());
            double sum = 0;
            for (size_t k = 0; k < exact.size(); ++k)
                sum += angleDegrees(exact[k], approximated[k]);
            row.push_back(sum / exact.size());
        }
        out.push_back(row);
    }
    return out;
}

// Table 1: the two surfaces' approximated normals (area weighting) on their shared edge.
std::vector<std::pair<double, double>> sharedEdgeDeviation(int continuity,
                                                           const std::vector<long>& counts,
                                                           BoundaryExtrapolation extrapolation) {
    const auto pair = adjacentSurfaces(continuity);
    std::vector<std::pair<double, double>> out;
    for (long count : counts) {
        const int n = static_cast<int>(std::lround(std::sqrt(double(count) / 2)));
        const auto us = uniform(0, 1, n), vs = uniform(0, 1, n);
        std::vector<Point3> p0, p1;
        std::vector<Vector3> n0(size_t(n) * n), n1(size_t(n) * n);
        GridEvaluator(pair[0]).evaluate(us, vs, p0, nullptr);
        GridEvaluator(pair[1]).evaluate(us, vs, p1, nullptr);
        approximateGridNormals(p0.data(), n, n, NormalWeighting::Area, n0.data(), extrapolation);
        approximateGridNormals(p1.data(), n, n, NormalWeighting::Area, n1.data(), extrapolation);
        double sum = 0, worst = 0;
        for (int i = 0; i < n; ++i) {
            // last column of the first surface (v = 1) against the first of the second (v = 0)
            const double a = angleDegrees(n0[size_t(i) * n + n - 1], n1[size_t(i) * n]);
            sum += a;
            worst = std::max(worst, a);
        }
        out.emplace_back(sum / n, worst);
    }
    return out;
}

Benchmark makeBenchmark(const EvaluationModel& model) {
    Benchmark b{model.name, model.surfaces, {}};
    for (const auto& s : b.surfaces) b.occt.push_back(testing::toOcctSurface(s));
    return b;
}

Benchmark corpusBenchmark(const std::filesystem::path& corpus) {
    Benchmark b{"corpus B-spline faces", {}, {}};
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(corpus)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        try {
            BRepBuilderAPI_NurbsConvert converter(occ::readShape(path.string()), Standard_False);
            TopTools_IndexedMapOfShape faces;
            TopExp::MapShapes(converter.Shape(), TopAbs_FACE, faces);
            for (int k = 1; k <= faces.Extent(); ++k) {
                auto occt = occ::faceSurfaceAsBSpline(TopoDS::Face(faces(k)));
                BSplineSurface ours = occ::toBSplineSurface(occt);
                if (ours.problem()) continue;
                b.surfaces.push_back(std::move(ours));
                b.occt.push_back(occt);
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "corpus: %s skipped: %s\n", path.filename().c_str(), e.what());
        } catch (const Standard_Failure& e) {
            std::fprintf(stderr, "corpus: %s skipped: %s\n", path.filename().c_str(),
                         e.GetMessageString());
        }
    }
    b.name += " (" + std::to_string(b.surfaces.size()) + ")";
    return b;
}

// The corners of a random adaptive (quadtree) subdivision of the domain: the kind of vertex set
// an adaptive tessellator evaluates, where many vertices share their u or v value.
std::vector<Point2> adaptiveCorners(const BSplineSurface& s, int depth, std::mt19937& random) {
    std::set<std::pair<double, double>> corners;
    std::uniform_real_distribution<double> coin(0, 1);
    std::function<void(double, double, double, double, int)> split =
        [&](double u0, double u1, double v0, double v1, int level) {
            if (level < depth && (level < 2 || coin(random) < 0.7)) {
                const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
                split(u0, um, v0, vm, level + 1);
                split(um, u1, v0, vm, level + 1);
                split(u0, um, vm, v1, level + 1);
                split(um, u1, vm, v1, level + 1);
                return;
            }
            for (double u : {u0, u1})
                for (double v : {v0, v1}) corners.insert({u, v});
        };
    split(s.knotsU().first(), s.knotsU().last(), s.knotsV().first(), s.knotsV().last(), 0);
    std::vector<Point2> out;
    for (const auto& [u, v] : corners) out.emplace_back(u, v);
    std::shuffle(out.begin(), out.end(), random);  // a tessellator's vertex order, not sorted
    return out;
}

struct ScatteredResult {
    std::string model;
    long vertices;
    double pointwise, pointSet, occt;  // seconds, points + exact normals
};

// Beyond the paper: scattered vertices, as FaceTessellator evaluates them today
// (BSplineSurface::point + BSplineSurface::normal per vertex) against PointSetEvaluator and
// OpenCASCADE's cached D1.
ScatteredResult scattered(const Benchmark& b, int depth, double budget) {
    std::mt19937 random(1);
    std::vector<std::vector<Point2>> sets;
    std::vector<PointSetEvaluator> evaluators;
    long vertices = 0;
    for (const auto& s : b.surfaces) {
        sets.push_back(adaptiveCorners(s, depth, random));
        evaluators.emplace_back(s);
        vertices += static_cast<long>(sets.back().size());
    }
    size_t largest = 0;
    for (const auto& set : sets) largest = std::max(largest, set.size());
    std::vector<Point3> points(largest);
    std::vector<Vector3> normals(largest);
    ScatteredResult r{b.name, vertices, 0, 0, 0};
    r.pointwise = bestSeconds(
        [&] {
            for (size_t s = 0; s < sets.size(); ++s)
                for (size_t k = 0; k < sets[s].size(); ++k) {
                    points[k] = b.surfaces[s].point(sets[s][k].x(), sets[s][k].y());
                    normals[k] = b.surfaces[s].normal(sets[s][k].x(), sets[s][k].y());
                }
            gSink += points[0].x();
        },
        3, budget);
    r.pointSet = bestSeconds(
        [&] {
            for (size_t s = 0; s < sets.size(); ++s)
                evaluators[s].evaluate(sets[s], points.data(), normals.data());
            gSink += points[0].x();
        },
        3, budget);
    r.occt = bestSeconds(
        [&] {
            for (size_t s = 0; s < sets.size(); ++s) {
                GeomAdaptor_Surface surface(b.occt[s]);
                for (size_t k = 0; k < sets[s].size(); ++k) {
                    gp_Pnt p;
                    gp_Vec du, dv;
                    surface.D1(sets[s][k].x(), sets[s][k].y(), p, du, dv);
                    occtPointAndNormal(p, du, dv, points[k], normals[k]);
                }
            }
            gSink += points[0].x();
        },
        3, budget);
    return r;
}

// Beyond the paper: scattered vertices of adaptive subdivisions, every model, printed as a table.
std::vector<ScatteredResult> scatteredTable(const std::vector<Benchmark>& benchmarks, bool quick,
                                            double budget) {
    std::printf(
        "\nScattered vertices (corners of random adaptive subdivisions), points + exact "
        "normals, one core\n");
    std::printf("%-28s %9s | %22s %8s | %22s %8s | %18s %8s | %8s\n", "model", "vertices",
                "BSplineSurface point+normal", "ns/vtx", "PointSetEvaluator", "ns/vtx",
                "OCCT GeomAdaptor D1", "ns/vtx", "gain");
    std::vector<ScatteredResult> results;
    for (const auto& b : benchmarks) {
        if (quick && b.name != "Utah teapot" && b.name != "Torus") continue;
        const int depth = b.surfaces.size() > 100 ? 5 : b.surfaces.size() > 10 ? 6 : 9;
        const auto r = scattered(b, depth, budget);
        const double n = double(r.vertices);
        std::printf("%-28s %9ld | %22.5f %8.1f | %22.5f %8.1f | %18.5f %8.1f | %7.1fx\n",
                    r.model.c_str(), r.vertices, r.pointwise, r.pointwise * 1e9 / n, r.pointSet,
                    r.pointSet * 1e9 / n, r.occt, r.occt * 1e9 / n, r.pointwise / r.pointSet);
        results.push_back(r);
    }
    return results;
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// Beyond the paper: the vertex sets the tessellator really evaluates. Every corpus model is
// tessellated (one thread) at a relative tolerance; each face's vertices (u, v) and whether the
// face needs their position (its own points) or only their normal (edge points) are then
// evaluated four ways: PointSetEvaluator as FaceTessellator does now (one evaluator per face,
// its set-up included), the former per-vertex BSplineSurface::point + BSplineSurface::normal,
// and OpenCASCADE's D1 (GeomAdaptor_Surface made per face, its BSplSLib cache included, and
// Geom_BSplineSurface::D1), each for the whole model.
struct TessellatorVertexResult {
    std::string model;
    double relative = 0;
    int faces = 0;
    long vertices = 0;     // face vertices: an edge point counts once per face that uses it
    long ownVertices = 0;  // of them, those whose position comes from the surface
    long distinctU = 0, distinctV = 0;  // summed over the faces
    double tessellationSeconds = 0;     // the whole tessellation (one thread, wall)
    double pointSet = 0, perVertex = 0, occtAdaptor = 0, occtSurface = 0;  // seconds
    double maxNormalDeviation = 0;           // PointSetEvaluator against Geom_BSplineSurface::D1
    double maxNormalDeviationPerVertex = 0;  // BSplineSurface::normal against the same
    double maxPointDeviation = 0;            // the same for points, relative to the model's size
};

std::vector<TessellatorVertexResult> tessellatorVertexSets(const std::filesystem::path& corpus,
                                                           double budget) {
    std::vector<TessellatorVertexResult> results;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(corpus)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        Model model;
        try {
            model = occ::importModel(occ::readShape(path.string()));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s skipped: %s\n", path.filename().c_str(), e.what());
            continue;
        } catch (const Standard_Failure& e) {
            std::fprintf(stderr, "%s skipped: %s\n", path.filename().c_str(), e.GetMessageString());
            continue;
        }
        std::vector<Handle(Geom_BSplineSurface)> occt;
        for (const auto& face : model.faces)
            occt.push_back(face.surface.problem() ? Handle(Geom_BSplineSurface)()
                                                  : testing::toOcctSurface(face.surface));
        for (double relative : {1e-3, 1e-4}) {
            std::fprintf(stderr, "tessellator vertices: %s at %g...\n", path.filename().c_str(),
                         relative);
            TessellationOptions options;
            options.tolerance = relative * model.boundingBoxDiagonal;
            options.threads = 1;
            options.keepFaceVertices = true;
            const TessellationResult tessellation = tessellateModel(model, options);
            TessellatorVertexResult r;
            r.model = path.filename().string();
            r.relative = relative;
            r.tessellationSeconds = tessellation.seconds;
            const auto& sets = tessellation.faceVertices;
            size_t largest = 0;
            std::vector<int> faces;  // the faces the tessellator evaluated
            for (size_t f = 0; f < sets.size(); ++f) {
                if (sets[f].uv.empty() || occt[f].IsNull()) continue;
                faces.push_back(static_cast<int>(f));
                largest = std::max(largest, sets[f].uv.size());
                r.vertices += static_cast<long>(sets[f].uv.size());
                for (char own : sets[f].needsPosition) r.ownVertices += own;
                std::set<double> us, vs;
                for (const auto& uv : sets[f].uv) us.insert(uv.x()), vs.insert(uv.y());
                r.distinctU += static_cast<long>(us.size());
                r.distinctV += static_cast<long>(vs.size());
            }
            r.faces = static_cast<int>(faces.size());
            if (faces.empty()) continue;
            std::vector<Point3> points(largest);
            std::vector<Vector3> normals(largest);
            r.pointSet = bestSeconds(
                [&] {
                    for (int f : faces)
                        PointSetEvaluator(model.faces[f].surface)
                            .evaluate(sets[f].uv, points.data(), normals.data());
                    gSink += points[0].x();
                },
                3, budget);
            r.perVertex = bestSeconds(
                [&] {
                    for (int f : faces) {
                        const BSplineSurface& s = model.faces[f].surface;
                        const auto& set = sets[f];
                        for (size_t k = 0; k < set.uv.size(); ++k) {
                            if (set.needsPosition[k])
                                points[k] = s.point(set.uv[k].x(), set.uv[k].y());
                            normals[k] = s.normal(set.uv[k].x(), set.uv[k].y());
                        }
                    }
                    gSink += points[0].x() + normals[0].x();
                },
                3, budget);
            auto occtRun = [&](bool adaptor) {
                return [&, adaptor] {
                    for (int f : faces) {
                        const auto& set = sets[f];
                        GeomAdaptor_Surface cached;
                        if (adaptor) cached.Load(occt[f]);
                        for (size_t k = 0; k < set.uv.size(); ++k) {
                            gp_Pnt p;
                            gp_Vec du, dv;
                            if (adaptor)
                                cached.D1(set.uv[k].x(), set.uv[k].y(), p, du, dv);
                            else
                                occt[f]->D1(set.uv[k].x(), set.uv[k].y(), p, du, dv);
                            occtPointAndNormal(p, du, dv, points[k], normals[k]);
                        }
                    }
                    gSink += points[0].x();
                };
            };
            r.occtAdaptor = bestSeconds(occtRun(true), 3, budget);
            r.occtSurface = bestSeconds(occtRun(false), 3, budget);
            // the evaluator's results against OpenCASCADE's (where du x dv has a direction)
            for (int f : faces) {
                const auto& set = sets[f];
                PointSetEvaluator(model.faces[f].surface)
                    .evaluate(set.uv, points.data(), normals.data());
                const BSplineSurface& s = model.faces[f].surface;
                for (size_t k = 0; k < set.uv.size(); ++k) {
                    // clamped as ours clamps; OpenCASCADE would extrapolate
                    const double u =
                        std::clamp(set.uv[k].x(), s.knotsU().first(), s.knotsU().last());
                    const double v =
                        std::clamp(set.uv[k].y(), s.knotsV().first(), s.knotsV().last());
                    gp_Pnt p;
                    gp_Vec du, dv;
                    occt[f]->D1(u, v, p, du, dv);
                    r.maxPointDeviation = std::max(
                        r.maxPointDeviation, (points[k] - Point3(p.X(), p.Y(), p.Z())).norm() /
                                                 model.boundingBoxDiagonal);
                    // where du x dv has a direction (not at a pole, where ours looks inside)
                    const Vector3 occtDu(du.X(), du.Y(), du.Z()), occtDv(dv.X(), dv.Y(), dv.Z());
                    const Vector3 n = occtDu.cross(occtDv);
                    if (!isReliableNormal(occtDu, occtDv, n)) continue;
                    const Vector3 occtNormal = n.normalized();
                    r.maxNormalDeviation =
                        std::max(r.maxNormalDeviation, (normals[k] - occtNormal).norm());
                    r.maxNormalDeviationPerVertex =
                        std::max(r.maxNormalDeviationPerVertex,
                                 (s.normal(set.uv[k].x(), set.uv[k].y()) - occtNormal).norm());
                }
            }
            results.push_back(r);
        }
    }
    return results;
}

void printTessellatorVertexSets(const std::vector<TessellatorVertexResult>& results) {
    std::printf(
        "\nThe tessellator's vertex sets (corpus, one core): points where the face needs them "
        "+ exact normals, ns per vertex; gain = per-vertex / PointSetEvaluator\n");
    std::printf("%-28s %6s %6s %8s %5s %6s | %9s %9s %9s %9s | %6s %6s | %9s %7s | %8s %8s %8s\n",
                "model", "rel", "faces", "vertices", "own", "u/vtx", "PointSet", "pervertex",
                "OCCT-ad", "OCCT-D1", "gain", "vsOCCT", "tess s", "eval %", "dP/diag", "dN",
                "dN old");
    for (const auto& r : results) {
        const double n = double(r.vertices);
        const double occtBest = std::min(r.occtAdaptor, r.occtSurface);
        std::printf(
            "%-28s %6.0e %6d %8ld %4.0f%% %6.2f | %9.1f %9.1f %9.1f %9.1f | %5.2fx %5.2fx | "
            "%9.3f %6.2f%% | %8.1e %8.1e %8.1e\n",
            r.model.c_str(), r.relative, r.faces, r.vertices, 100.0 * r.ownVertices / n,
            r.distinctU / n, r.pointSet * 1e9 / n, r.perVertex * 1e9 / n, r.occtAdaptor * 1e9 / n,
            r.occtSurface * 1e9 / n, r.perVertex / r.pointSet, occtBest / r.pointSet,
            r.tessellationSeconds, 100.0 * r.pointSet / r.tessellationSeconds, r.maxPointDeviation,
            r.maxNormalDeviation, r.maxNormalDeviationPerVertex);
    }
}

void writeTessellatorVertexSets(std::ostream& j,
                                const std::vector<TessellatorVertexResult>& results) {
    j << "  \"tessellator_vertices\": [\n";
    for (size_t k = 0; k < results.size(); ++k) {
        const auto& r = results[k];
        j << "    {\"model\": " << jsonString(r.model) << ", \"relative\": " << r.relative
          << ", \"faces\": " << r.faces << ", \"vertices\": " << r.vertices
          << ", \"own_vertices\": " << r.ownVertices << ", \"distinct_u\": " << r.distinctU
          << ", \"distinct_v\": " << r.distinctV
          << ", \"tessellation_seconds\": " << r.tessellationSeconds
          << ", \"point_set_evaluator_seconds\": " << r.pointSet
          << ", \"per_vertex_seconds\": " << r.perVertex
          << ", \"occt_adaptor_seconds\": " << r.occtAdaptor
          << ", \"occt_surface_d1_seconds\": " << r.occtSurface
          << ", \"max_point_deviation_relative\": " << r.maxPointDeviation
          << ", \"max_normal_deviation\": " << r.maxNormalDeviation
          << ", \"max_normal_deviation_per_vertex\": " << r.maxNormalDeviationPerVertex << "}"
          << (k + 1 < results.size() ? "," : "") << "\n";
    }
    j << "  ]";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The evaluation paper's study (Tables 1-5) with OpenCASCADE as the peer"};
    bool quick = false;
    std::string jsonPath, corpus = NURBSLOD_CORPUS_DIR;
    int threads = 2;
    double budget = 0.3;
    app.add_flag("--quick", quick, "small grids only: a smoke run of seconds");
    app.add_option("--json", jsonPath, "write the figures as JSON to this file");
    app.add_option("--threads", threads, "threads for the extra threaded grid-evaluator row")
        ->check(CLI::Range(1, 256));
    app.add_option("--budget", budget, "seconds spent per measurement before taking the best")
        ->check(CLI::Range(0.0, 60.0));
    app.add_option("--corpus", corpus, "folder of models whose B-spline faces are benchmarked too");
    bool tessellatorOnly = false, scatteredOnly = false;
    app.add_flag("--tessellator-vertices", tessellatorOnly,
                 "only the table of the tessellator's vertex sets (corpus models)");
    app.add_flag("--scattered", scatteredOnly,
                 "only the table of scattered vertices (adaptive subdivisions)");
    CLI11_PARSE(app, argc, argv);
    if (tessellatorOnly) {
        if (!std::filesystem::is_directory(corpus)) {
            std::printf("corpus not found at %s: nothing to measure\n", corpus.c_str());
            return 0;
        }
        const auto results = tessellatorVertexSets(corpus, budget);
        printTessellatorVertexSets(results);
        if (!jsonPath.empty()) {
            std::ofstream out(jsonPath);
            out << "{\n";
            writeTessellatorVertexSets(out, results);
            out << "\n}\n";
            if (!out) {
                std::fprintf(stderr, "cannot write %s\n", jsonPath.c_str());
                return 1;
            }
        }
        return gSink == 12345.678 ? 2 : 0;
    }
    if (quick) budget = std::min(budget, 0.02);

    std::printf("evaluation benchmark: AVX2+FMA %s, %s mode, one core unless a row says so\n",
                GridEvaluator::avx2Available() ? "available" : "NOT available",
                quick ? "quick" : "full");

    // Table 5. The bicubic sheet (a single bicubic surface, 8 x 8 spans) is the issue's
    // bicubic 1M-vertex grid.
    std::vector<Benchmark> benchmarks;
    std::vector<long> paperCounts;
    const EvaluationModel bicubic{"Bicubic 8x8 spans", {}, 0};
    {
        std::vector<EvaluationModel> models = evaluationStudyModels();
        // the bicubic sheet, built as the study sheets are
        KnotVector k(3, {0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 8, 8, 8});
        std::vector<HomogeneousPoint3> poles;
        for (int i = 0; i < 11; ++i)
            for (int j = 0; j < 11; ++j) {
                const double x = i / 10.0, y = j / 10.0;
                const double z = 0.15 * std::sin(7 * x + 1) * std::cos(5 * y) + 0.1 * x * y;
                poles.emplace_back(x, y, z, 1.0);
            }
        models.push_back({"Bicubic 8x8 spans", {BSplineSurface(k, k, 11, 11, poles)}, 10000});
        for (const auto& m : models) {
            benchmarks.push_back(makeBenchmark(m));
            paperCounts.push_back(m.vertexCount);
        }
    }
    if (!quick && std::filesystem::is_directory(corpus)) {
        benchmarks.push_back(corpusBenchmark(corpus));
        paperCounts.push_back(100000);
    }
    if (scatteredOnly) {
        scatteredTable(benchmarks, quick, budget);
        return gSink == 12345.678 ? 2 : 0;
    }
    std::vector<Row> rows;
    double occtBicubic = 0, bestBicubic = 0, occtDegree15 = 0, bestDegree15 = 0;
    std::string bestBicubicMethod, bestDegree15Method;
    long bicubicVertices = 0;
    for (size_t b = 0; b < benchmarks.size(); ++b) {
        std::vector<long> counts = {paperCounts[b]};
        const bool isBicubic = benchmarks[b].name == bicubic.name;
        const bool isDegree15 = benchmarks[b].name == "Sup.15x15";
        if (quick) {
            counts = {std::min(paperCounts[b], 4000L)};
            if (isBicubic) counts = {40000};
        } else if (benchmarks[b].name.rfind("corpus", 0) != 0) {
            counts.push_back(1000000);
        }
        for (long count : counts) {
            std::fprintf(stderr, "timing %s at %ld vertices...\n", benchmarks[b].name.c_str(),
                         count);
            auto r = table5For(benchmarks[b], count, threads, budget);
            if ((isBicubic || isDegree15) && count == counts.back()) {
                double occt = 1e300, best = 1e300;
                std::string bestName;
                for (const auto& row : r) {
                    if (row.method.rfind("OCCT", 0) == 0)
                        occt = std::min(occt, row.seconds[1]);
                    else if (row.method.find("threads") == std::string::npos &&
                             row.seconds[1] < best) {
                        best = row.seconds[1];
                        bestName = row.method;
                    }
                }
                const double n = double(r.front().vertices);
                if (isBicubic) {
                    occtBicubic = occt * 1e9 / n;
                    bestBicubic = best * 1e9 / n;
                    bestBicubicMethod = bestName;
                    bicubicVertices = r.front().vertices;
                } else {
                    occtDegree15 = occt * 1e9 / n;
                    bestDegree15 = best * 1e9 / n;
                    bestDegree15Method = bestName;
                }
            }
            rows.insert(rows.end(), r.begin(), r.end());
        }
    }
    std::printf(
        "\nTable 5: evaluation time per method and model (best of runs; 'vs OCCT' = the "
        "faster OpenCASCADE path with exact normals / this row, exact normals)\n");
    printTable5(rows);
    std::printf(
        "\nBicubic grid of %ld vertices, points + exact normals, one core: OCCT %.1f "
        "ns/vertex, best (%s) %.2f ns/vertex: %.1fx, %.1f M vertices/s\n",
        bicubicVertices, occtBicubic, bestBicubicMethod.c_str(), bestBicubic,
        occtBicubic / bestBicubic, 1e3 / bestBicubic);
    if (bestDegree15 > 0)
        std::printf(
            "Degree 15, points + exact normals, one core: OCCT %.1f ns/vertex, best (%s) "
            "%.2f ns/vertex: %.1fx\n",
            occtDegree15, bestDegree15Method.c_str(), bestDegree15, occtDegree15 / bestDegree15);

    // Table 2: cost of the weightings, boundary extrapolation included
    std::printf("\nTable 2: approximated normals alone, seconds (from the points of the grid)\n");
    std::printf("%-22s %9s | %10s %10s %12s %10s\n", "model", "vertices", "uniform", "area",
                "inverse area", "angle");
    struct WeightingCase {
        EvaluationModel model;
        long vertices;
    };
    std::vector<std::pair<std::string, std::vector<double>>> table2;
    for (const auto& c : {WeightingCase{goblet(), 40000}, WeightingCase{torus(), 40000},
                          WeightingCase{teapot(), 5000}}) {
        const Benchmark b = makeBenchmark(c.model);
        long actual = 0;
        const auto jobs = gridJobs(b, c.vertices, actual);
        std::vector<std::vector<Point3>> points;
        for (const auto& j : jobs) {
            points.emplace_back();
            GridEvaluator(*j.surface).evaluate(j.us, j.vs, points.back(), nullptr);
        }
        std::vector<Vector3> normals(points.front().size());
        std::vector<double> seconds;
        for (NormalWeighting w : kWeightings)
            seconds.push_back(bestSeconds(
                [&] {
                    for (size_t s = 0; s < jobs.size(); ++s)
                        approximateGridNormals(points[s].data(), int(jobs[s].us.size()),
                                               int(jobs[s].vs.size()), w, normals.data());
                },
                3, budget));
        std::printf("%-22s %9ld | %10.6f %10.6f %12.6f %10.6f\n", c.model.name.c_str(), actual,
                    seconds[0], seconds[1], seconds[2], seconds[3]);
        table2.emplace_back(c.model.name, seconds);
    }

    // Tables 3 and 4
    const std::vector<long> counts = {40000, 32000, 21000, 9000, 1600};
    std::vector<std::pair<std::string, std::vector<std::vector<double>>>> deviations;
    for (const auto& model : {torus(), goblet()}) {
        const auto table = deviationTable(model.surfaces.front(), counts);
        std::printf("\nTable %d: mean angle (degrees) between approximated and exact normals, %s\n",
                    model.name == "Torus" ? 3 : 4, model.name.c_str());
        std::printf("%9s | %8s %8s %12s %8s\n", "vertices", "uniform", "area", "inverse area",
                    "angle");
        for (size_t k = 0; k < counts.size(); ++k)
            std::printf("%9ld | %8.4f %8.4f %12.4f %8.4f\n", counts[k], table[k][0], table[k][1],
                        table[k][2], table[k][3]);
        deviations.emplace_back(model.name, table);
    }

    // Table 1
    std::printf(
        "\nTable 1: angle (degrees) between the approximated normals (area) of two "
        "adjacent surfaces on their shared edge\n");
    std::printf("%9s | %10s %10s | %10s %10s || %10s %10s | %10s %10s\n", "", "paper's",
                "reflection", "", "", "linear", "(beyond", "the paper)", "");
    std::printf("%9s | %10s %10s | %10s %10s || %10s %10s | %10s %10s\n", "vertices", "C1 mean",
                "C1 max", "C2 mean", "C2 max", "C1 mean", "C1 max", "C2 mean", "C2 max");
    const auto c1 = sharedEdgeDeviation(1, counts, BoundaryExtrapolation::Reflection),
               c2 = sharedEdgeDeviation(2, counts, BoundaryExtrapolation::Reflection),
               c1Linear = sharedEdgeDeviation(1, counts, BoundaryExtrapolation::Linear),
               c2Linear = sharedEdgeDeviation(2, counts, BoundaryExtrapolation::Linear);
    for (size_t k = 0; k < counts.size(); ++k)
        std::printf("%9ld | %10.4f %10.4f | %10.4f %10.4f || %10.4f %10.4f | %10.4f %10.4f\n",
                    counts[k], c1[k].first, c1[k].second, c2[k].first, c2[k].second,
                    c1Linear[k].first, c1Linear[k].second, c2Linear[k].first, c2Linear[k].second);

    const std::vector<ScatteredResult> scatteredResults = scatteredTable(benchmarks, quick, budget);
    std::vector<TessellatorVertexResult> tessellatorResults;
    if (!quick && std::filesystem::is_directory(corpus)) {
        tessellatorResults = tessellatorVertexSets(corpus, budget);
        printTessellatorVertexSets(tessellatorResults);
    }

    if (!jsonPath.empty()) {
        std::ostringstream j;
        j.precision(6);
        j << "{\n  \"quick\": " << (quick ? "true" : "false") << ",\n";
        j << "  \"bicubic_vertices\": " << bicubicVertices << ",\n";
        j << "  \"occt_ns_per_vertex_normals\": " << occtBicubic << ",\n";
        j << "  \"best_ns_per_vertex_normals\": " << bestBicubic << ",\n";
        j << "  \"best_method_normals\": " << jsonString(bestBicubicMethod) << ",\n";
        j << "  \"degree15_occt_ns_per_vertex_normals\": " << occtDegree15 << ",\n";
        j << "  \"degree15_best_ns_per_vertex_normals\": " << bestDegree15 << ",\n";
        j << "  \"table5\": [\n";
        for (size_t k = 0; k < rows.size(); ++k) {
            const auto& r = rows[k];
            j << "    {\"model\": " << jsonString(r.model)
              << ", \"method\": " << jsonString(r.method) << ", \"vertices\": " << r.vertices;
            for (Mode m : {Mode::Points, Mode::ExactNormals, Mode::ApproximatedNormals})
                j << ", " << jsonString(std::string(modeName(m)) + " seconds") << ": "
                  << r.seconds[int(m)];
            j << "}" << (k + 1 < rows.size() ? "," : "") << "\n";
        }
        j << "  ],\n  \"table2_seconds\": {";
        for (size_t k = 0; k < table2.size(); ++k) {
            j << (k ? ", " : "") << jsonString(table2[k].first) << ": [";
            for (size_t w = 0; w < 4; ++w) j << (w ? ", " : "") << table2[k].second[w];
            j << "]";
        }
        j << "},\n  \"weightings\": [\"uniform\", \"area\", \"inverse area\", \"angle\"],\n";
        j << "  \"deviation_vertices\": [40000, 32000, 21000, 9000, 1600],\n";
        j << "  \"tables3_4_degrees\": {";
        for (size_t m = 0; m < deviations.size(); ++m) {
            j << (m ? ", " : "") << jsonString(deviations[m].first) << ": [";
            for (size_t k = 0; k < counts.size(); ++k) {
                j << (k ? ", " : "") << "[";
                for (size_t w = 0; w < 4; ++w) j << (w ? ", " : "") << deviations[m].second[k][w];
                j << "]";
            }
            j << "]";
        }
        j << "},\n  \"table1_degrees\": {";
        const std::pair<const char*, const std::vector<std::pair<double, double>>*> table1[] = {
            {"C1", &c1}, {"C2", &c2}, {"C1_linear", &c1Linear}, {"C2_linear", &c2Linear}};
        for (size_t t = 0; t < std::size(table1); ++t) {
            j << (t ? "], " : "") << jsonString(table1[t].first) << ": [";
            for (size_t k = 0; k < counts.size(); ++k)
                j << (k ? ", " : "") << "[" << (*table1[t].second)[k].first << ", "
                  << (*table1[t].second)[k].second << "]";
        }
        j << "]},\n  \"scattered\": [\n";
        for (size_t k = 0; k < scatteredResults.size(); ++k) {
            const auto& r = scatteredResults[k];
            j << "    {\"model\": " << jsonString(r.model) << ", \"vertices\": " << r.vertices
              << ", \"bsplinesurface_seconds\": " << r.pointwise
              << ", \"point_set_evaluator_seconds\": " << r.pointSet
              << ", \"occt_adaptor_seconds\": " << r.occt << "}"
              << (k + 1 < scatteredResults.size() ? "," : "") << "\n";
        }
        j << "  ],\n";
        writeTessellatorVertexSets(j, tessellatorResults);
        j << "\n}\n";
        std::ofstream out(jsonPath);
        out << j.str();
        if (!out) {
            std::fprintf(stderr, "cannot write %s\n", jsonPath.c_str());
            return 1;
        }
    }
    return gSink == 12345.678 ? 2 : 0;
}
