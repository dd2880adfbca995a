// Bridge from symdecomp to OpenSubdiv: uniform Catmull-Clark refinement of a quad mesh in
// double precision, reading back a vertex and its ordered 1-ring at every level.
//
// Built as a shared library by symdecomp/opensubdiv/build.py (g++, -losdCPU) and called from
// Python through ctypes (symdecomp/opensubdiv/__init__.py). Nothing here knows about the
// paper: it only drives Far::TopologyRefiner and Far::PrimvarRefinerReal<double>.

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <vector>

using namespace OpenSubdiv;

namespace {

struct Point {
    double p[3];
    void Clear(void * = nullptr) { p[0] = p[1] = p[2] = 0.0; }
    void AddWithWeight(Point const &src, double w) {
        p[0] += w * src.p[0];
        p[1] += w * src.p[1];
        p[2] += w * src.p[2];
    }
};

void set_error(char *error, int error_len, const char *message) {
    if (error && error_len > 0) {
        std::snprintf(error, static_cast<size_t>(error_len), "%s", message);
    }
}

// OpenSubdiv reports errors through a callback (by default it prints them); keep the last one.
char last_osd_error[512];
bool osd_failed = false;

void record_error(Far::ErrorType, const char *message) {
    osd_failed = true;
    std::snprintf(last_osd_error, sizeof(last_osd_error), "OpenSubdiv: %s", message);
}

bool face_has(Far::TopologyLevel const &level, Far::Index f, Far::Index v) {
    Far::ConstIndexArray fv = level.GetFaceVertices(f);
    for (int k = 0; k < fv.size(); ++k) {
        if (fv[k] == v) return true;
    }
    return false;
}

}  // namespace

// A refiner for a mesh of `per_face`-gons under `scheme` (boundary: edges only), refined uniformly
// `levels` times with the full topology in the last level (the limit masks need it), or nullptr
// with the message in `error` when OpenSubdiv rejects the topology.
static std::unique_ptr<Far::TopologyRefiner> make_refiner(Sdc::SchemeType scheme, int per_face, int n_vertices, int n_faces,
                                                          const int *face_vertices, int levels, char *error, int error_len) {
    std::vector<int> verts_per_face(static_cast<size_t>(n_faces), per_face);
    Far::TopologyDescriptor desc;
    desc.numVertices = n_vertices;
    desc.numFaces = n_faces;
    desc.numVertsPerFace = verts_per_face.data();
    desc.vertIndicesPerFace = face_vertices;
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, sdc)));
    if (!refiner || osd_failed) {
        set_error(error, error_len, osd_failed ? last_osd_error : "OpenSubdiv rejected the mesh topology");
        return nullptr;
    }
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);
    return refiner;
}

// Room for the points of every level, the base level's filled from `positions` (3 doubles each).
static std::vector<Point> base_points(Far::TopologyRefiner const &refiner, int n_vertices, const double *positions) {
    std::vector<Point> buffer(static_cast<size_t>(refiner.GetNumVerticesTotal()));
    for (int v = 0; v < n_vertices; ++v) {
        for (int c = 0; c < 3; ++c) buffer[v].p[c] = positions[3 * v + c];
    }
    return buffer;
}

// Interpolate the base points of `buffer` through levels 1..levels; returns where each level starts.
static std::vector<Point *> interpolate(Far::TopologyRefiner const &refiner, Far::PrimvarRefinerReal<double> const &primvar,
                                        std::vector<Point> &buffer, int levels) {
    std::vector<Point *> level_start(static_cast<size_t>(levels) + 1);
    level_start[0] = buffer.data();
    for (int level = 1; level <= levels; ++level) {
        level_start[level] = level_start[level - 1] + refiner.GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, level_start[level - 1], level_start[level]);
    }
    return level_start;
}

// True, with OpenSubdiv's message in `error`, when OpenSubdiv reported an error since the call began.
static bool osd_error(char *error, int error_len) {
    if (osd_failed) set_error(error, error_len, last_osd_error);
    return osd_failed;
}

// Run an entry point's body with OpenSubdiv's errors recorded, and any C++ exception turned into
// return code 9 with its message in `error` (nothing may propagate through the C interface).
template <typename Body>
static int guarded(char *error, int error_len, Body body) {
    try {
        osd_failed = false;
        Far::SetErrorCallback(record_error);
        return body();
    } catch (std::exception const &exc) {
        set_error(error, error_len, exc.what());
        return 9;
    } catch (...) {
        set_error(error, error_len, "unknown C++ exception");
        return 9;
    }
}

extern "C" {

// Version of this bridge's C interface (bumped when the signature changes).
int symdecomp_osd_bridge_version() { return 2; }

// Refine the quad mesh `levels` times with OpenSubdiv's Catmull-Clark scheme and write, for
// every level 0..levels, the points (O, a_0..a_{n-1}, b_0..b_{n-1}) of the 1-ring of `center`
// into rings_out ((levels+1) * (2n+1) * 3 doubles). ring_a[i] is the edge neighbour a_i and
// ring_faces[i] the face (O, a_i, b_i, a_{i+1}) of the base mesh. limit_out receives the limit
// position of the central vertex computed by OpenSubdiv's limit mask from the last level
// (3 doubles). Returns 0 on success, nonzero (with a message in `error`) on failure.
int symdecomp_osd_refine_ring(int n_vertices, int n_faces, const int *face_vertices,
                              const double *positions, int center, int n, const int *ring_a,
                              const int *ring_faces, int levels, double *rings_out,
                              double *limit_out, char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        if (n_vertices <= 0 || n_faces <= 0 || n < 3 || levels < 0) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_refiner(Sdc::SCHEME_CATMARK, 4, n_vertices, n_faces, face_vertices, levels, error, error_len);
        if (!refiner) return 2;
        std::vector<Point> buffer = base_points(*refiner, n_vertices, positions);
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        std::vector<Point *> level_start = interpolate(*refiner, primvar, buffer, levels);

        std::vector<int> a(ring_a, ring_a + n), faces(ring_faces, ring_faces + n);
        int o = center;
        const int stride = 3 * (2 * n + 1);
        for (int level = 0; level <= levels; ++level) {
            Far::TopologyLevel const &topo = refiner->GetLevel(level);
            Point const *pts = level_start[level];
            double *out = rings_out + static_cast<size_t>(level) * stride;
            for (int i = 0; i < n; ++i) {
                Far::ConstIndexArray fv = topo.GetFaceVertices(faces[i]);
                int k = -1;
                for (int m = 0; m < fv.size(); ++m) {
                    if (fv[m] == o) k = m;
                }
                if (fv.size() != 4 || k < 0 || fv[(k + 1) % 4] != a[i] || fv[(k + 3) % 4] != a[(i + 1) % n]) {
                    set_error(error, error_len, "1-ring face is not (O, a_i, b_i, a_{i+1}) in order");
                    return 3;
                }
                int b = fv[(k + 2) % 4];
                for (int c = 0; c < 3; ++c) {
                    out[3 * (1 + i) + c] = pts[a[i]].p[c];
                    out[3 * (1 + n + i) + c] = pts[b].p[c];
                }
            }
            for (int c = 0; c < 3; ++c) out[c] = pts[o].p[c];
            if (level == levels) break;
            // Follow the 1-ring to the next level: O -> its vertex point, a_i -> the edge point of
            // (O, a_i), face i -> its child face at the corner O.
            int o_next = topo.GetVertexChildVertex(o);
            Far::TopologyLevel const &child = refiner->GetLevel(level + 1);
            std::vector<int> a_next(n), faces_next(n);
            for (int i = 0; i < n; ++i) {
                Far::Index e = topo.FindEdge(o, a[i]);
                if (e < 0) {
                    set_error(error, error_len, "a_i is not an edge neighbour of O");
                    return 4;
                }
                a_next[i] = topo.GetEdgeChildVertex(e);
                Far::ConstIndexArray kids = topo.GetFaceChildFaces(faces[i]);
                faces_next[i] = -1;
                for (int m = 0; m < kids.size(); ++m) {
                    if (face_has(child, kids[m], o_next)) faces_next[i] = kids[m];
                }
                if (faces_next[i] < 0) {
                    set_error(error, error_len, "no child face at the central vertex");
                    return 5;
                }
            }
            o = o_next;
            a = a_next;
            faces = faces_next;
        }

        std::vector<Point> limit(static_cast<size_t>(refiner->GetLevel(levels).GetNumVertices()));
        Point *limit_dst = limit.data();
        primvar.Limit(level_start[levels], limit_dst);
        if (osd_error(error, error_len)) return 6;
        for (int c = 0; c < 3; ++c) limit_out[c] = limit[o].p[c];
        return 0;
    });
}

}  // extern "C"

// Refine a mesh of `verts_per_face`-gons `levels` times (uniform, `scheme`) and write, for every
// vertex of the last level, its refined position (points_out) and OpenSubdiv's limit position
// (Far::PrimvarRefiner::Limit; limits_out), 3 doubles each. *count receives the number of
// last-level vertices; if it exceeds `capacity` nothing is written and 7 is returned.
static int limit_points(Sdc::SchemeType scheme, int verts_per_face_count, int n_vertices, int n_faces,
                        const int *face_vertices, const double *positions, int levels, int capacity,
                        int *count, double *points_out, double *limits_out, char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        if (n_vertices <= 0 || n_faces <= 0 || levels < 0) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_refiner(scheme, verts_per_face_count, n_vertices, n_faces, face_vertices, levels, error, error_len);
        if (!refiner) return 2;
        const int last = refiner->GetLevel(levels).GetNumVertices();
        *count = last;
        if (last > capacity) {
            set_error(error, error_len, "output capacity too small");
            return 7;
        }
        std::vector<Point> buffer = base_points(*refiner, n_vertices, positions);
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        Point *src = interpolate(*refiner, primvar, buffer, levels).back();
        std::vector<Point> limit(static_cast<size_t>(last));
        Point *limit_dst = limit.data();
        primvar.Limit(src, limit_dst);
        if (osd_error(error, error_len)) return 6;
        for (int v = 0; v < last; ++v) {
            for (int c = 0; c < 3; ++c) {
                points_out[3 * v + c] = src[v].p[c];
                limits_out[3 * v + c] = limit[v].p[c];
            }
        }
        return 0;
    });
}

extern "C" {

// limit_points with OpenSubdiv's Catmull-Clark scheme on a quad mesh.
int symdecomp_osd_limit_points(int n_vertices, int n_faces, const int *face_vertices,
                               const double *positions, int levels, int capacity, int *count,
                               double *points_out, double *limits_out, char *error,
                               int error_len) {
    return limit_points(Sdc::SCHEME_CATMARK, 4, n_vertices, n_faces, face_vertices, positions, levels,
                        capacity, count, points_out, limits_out, error, error_len);
}

// limit_points with OpenSubdiv's Loop scheme on a triangle mesh.
int symdecomp_osd_loop_limit_points(int n_vertices, int n_faces, const int *face_vertices,
                                    const double *positions, int levels, int capacity, int *count,
                                    double *points_out, double *limits_out, char *error,
                                    int error_len) {
    return limit_points(Sdc::SCHEME_LOOP, 3, n_vertices, n_faces, face_vertices, positions, levels,
                        capacity, count, points_out, limits_out, error, error_len);
}

}  // extern "C"

// ---------------------------------------------------------------------------------------------
// Loop's scheme on triangle meshes (a separate entry point; the Catmull-Clark one is above).

extern "C" {

// Refine the triangle mesh once with OpenSubdiv's Loop scheme. For every base vertex v,
// vertex_out[3v..] is its child vertex point, limit_out[3v..] the limit position of that
// child (= the limit of v) and tan1_out, tan2_out its two limit tangents (OpenSubdiv's
// first derivatives); all are NaN for a vertex without a child. For each of the
// n_edges pairs (edges[2i], edges[2i+1]), edge_out[3i..] is the edge point. Returns 0 on
// success, nonzero (with a message in `error`) on failure.
int symdecomp_osd_loop_step(int n_vertices, int n_faces, const int *face_vertices, const double *positions,
                            int n_edges, const int *edges, double *vertex_out, double *edge_out,
                            double *limit_out, double *tan1_out, double *tan2_out, char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        if (n_vertices <= 0 || n_faces <= 0 || n_edges < 0) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_refiner(Sdc::SCHEME_LOOP, 3, n_vertices, n_faces, face_vertices, 1, error, error_len);
        if (!refiner) return 2;
        std::vector<Point> buffer = base_points(*refiner, n_vertices, positions);
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        Point *fine = interpolate(*refiner, primvar, buffer, 1)[1];
        size_t fine_count = static_cast<size_t>(refiner->GetLevel(1).GetNumVertices());
        std::vector<Point> limit(fine_count), tan1(fine_count), tan2(fine_count);
        Point *limit_dst = limit.data();
        Point *tan1_dst = tan1.data();
        Point *tan2_dst = tan2.data();
        primvar.Limit(fine, limit_dst, tan1_dst, tan2_dst);
        if (osd_error(error, error_len)) return 6;
        Far::TopologyLevel const &base = refiner->GetLevel(0);
        for (int v = 0; v < n_vertices; ++v) {
            Far::Index child = base.GetVertexChildVertex(v);
            for (int c = 0; c < 3; ++c) {
                vertex_out[3 * v + c] = child < 0 ? std::nan("") : fine[child].p[c];
                limit_out[3 * v + c] = child < 0 ? std::nan("") : limit[child].p[c];
                tan1_out[3 * v + c] = child < 0 ? std::nan("") : tan1[child].p[c];
                tan2_out[3 * v + c] = child < 0 ? std::nan("") : tan2[child].p[c];
            }
        }
        for (int i = 0; i < n_edges; ++i) {
            Far::Index e = base.FindEdge(edges[2 * i], edges[2 * i + 1]);
            if (e < 0) {
                set_error(error, error_len, "a requested edge is not in the mesh");
                return 4;
            }
            Far::Index child = base.GetEdgeChildVertex(e);
            for (int c = 0; c < 3; ++c) edge_out[3 * i + c] = fine[child].p[c];
        }
        return 0;
    });
}

}  // extern "C"

// ---------------------------------------------------------------------------------------------
// Limit frames of a whole mesh: for every vertex of the base mesh, OpenSubdiv's limit position and
// its two first derivatives (Far::PrimvarRefiner::Limit on the unrefined mesh), 3 doubles each.
// `loop` nonzero: Loop's scheme on triangles; else Catmull-Clark on quads. Boundary: edges only.

extern "C" {

int symdecomp_osd_limit_frames(int loop, int n_vertices, int n_faces, const int *face_vertices,
                               const double *positions, double *limits_out, double *du_out,
                               double *dv_out, char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        if (n_vertices <= 0 || n_faces <= 0) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_refiner(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, loop ? 3 : 4, n_vertices, n_faces,
                         face_vertices, 0, error, error_len);
        if (!refiner) return 2;
        std::vector<Point> points = base_points(*refiner, n_vertices, positions);
        std::vector<Point> limit(static_cast<size_t>(n_vertices)), du(limit.size()), dv(limit.size());
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        Point *limit_dst = limit.data(), *du_dst = du.data(), *dv_dst = dv.data();
        primvar.Limit(points.data(), limit_dst, du_dst, dv_dst);
        if (osd_error(error, error_len)) return 6;
        for (int v = 0; v < n_vertices; ++v) {
            for (int c = 0; c < 3; ++c) {
                limits_out[3 * v + c] = limit[v].p[c];
                du_out[3 * v + c] = du[v].p[c];
                dv_out[3 * v + c] = dv[v].p[c];
            }
        }
        return 0;
    });
}

}  // extern "C"

// ---------------------------------------------------------------------------------------------
// Sharp features: boundary interpolation, creasing method, edge and vertex sharpness.
//
// `options` is {scheme (0 Catmull-Clark, 1 Loop), boundary (0 none, 1 edge-only, 2 edge-and-corner),
// creasing (0 uniform, 1 Chaikin)}; `tags` holds the sharpness arrays of Far::TopologyDescriptor
// (crease vertex pairs and weights, corner vertices and weights; sharpness >= 10 is infinite).

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>

namespace {

struct SharpTags {
    int n_creases;
    const int *crease_pairs;
    const float *crease_weights;
    int n_corners;
    const int *corner_vertices;
    const float *corner_weights;
};

// A value with up to kDim weights: the columns of a one-step matrix or of limit masks at once.
const int kDim = 64;
struct Vec {
    double p[kDim];
    void Clear(void * = nullptr) {
        for (double &x : p) x = 0.0;
    }
    void AddWithWeight(Vec const &src, double w) {
        for (int c = 0; c < kDim; ++c) p[c] += w * src.p[c];
    }
};

// The topology descriptor and Sdc options of a tagged mesh, or nullptr (message in `error`).
std::unique_ptr<Far::TopologyRefiner> make_sharp_refiner(const int *options, int per_face, int n_vertices, int n_faces,
                                                         const int *face_vertices, SharpTags const &tags, char *error,
                                                         int error_len) {
    if (options[0] < 0 || options[0] > 1 || options[1] < 0 || options[1] > 2 || options[2] < 0 || options[2] > 1 ||
        per_face != (options[0] == 1 ? 3 : 4)) {
        set_error(error, error_len, "bad options");
        return nullptr;
    }
    std::vector<int> verts_per_face(static_cast<size_t>(n_faces), per_face);
    Far::TopologyDescriptor desc;
    desc.numVertices = n_vertices;
    desc.numFaces = n_faces;
    desc.numVertsPerFace = verts_per_face.data();
    desc.vertIndicesPerFace = face_vertices;
    desc.numCreases = tags.n_creases;
    desc.creaseVertexIndexPairs = tags.crease_pairs;
    desc.creaseWeights = tags.crease_weights;
    desc.numCorners = tags.n_corners;
    desc.cornerVertexIndices = tags.corner_vertices;
    desc.cornerWeights = tags.corner_weights;
    Sdc::Options sdc;
    const Sdc::Options::VtxBoundaryInterpolation boundary[] = {
        Sdc::Options::VTX_BOUNDARY_NONE, Sdc::Options::VTX_BOUNDARY_EDGE_ONLY, Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER};
    sdc.SetVtxBoundaryInterpolation(boundary[options[1]]);
    sdc.SetCreasingMethod(options[2] ? Sdc::Options::CREASE_CHAIKIN : Sdc::Options::CREASE_UNIFORM);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    Sdc::SchemeType scheme = options[0] == 1 ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, sdc)));
    if (!refiner || osd_failed) {
        set_error(error, error_len, osd_failed ? last_osd_error : "OpenSubdiv rejected the mesh topology");
        return nullptr;
    }
    return refiner;
}

// The ring (O, a_0..a_{n_a-1}, b_0..b_{n_f-1} on quads) of a centre followed from level 0 to `level`:
// O -> its child vertex, a_i -> the child of edge (O, a_i), face j -> its child face at O's child.
// Face j must be (O, a_j, b_j, a_{j+1}) (quads) or (O, a_j, a_{j+1}) (triangles), indices mod n_a.
// Returns 0 and the ring's vertex indices at `level`, or an error code.
int follow_ring(Far::TopologyRefiner const &refiner, int per_face, int center, int n_a, const int *ring_a, int n_f,
                const int *ring_faces, int level, std::vector<int> &ring, char *error, int error_len) {
    int o = center;
    std::vector<int> a(ring_a, ring_a + n_a), faces(ring_faces, ring_faces + n_f);
    for (int l = 0;; ++l) {
        Far::TopologyLevel const &topo = refiner.GetLevel(l);
        ring.assign(1, o);
        ring.insert(ring.end(), a.begin(), a.end());
        for (int j = 0; j < n_f; ++j) {
            Far::ConstIndexArray fv = topo.GetFaceVertices(faces[j]);
            int k = -1;
            for (int m = 0; m < fv.size(); ++m) {
                if (fv[m] == o) k = m;
            }
            if (fv.size() != per_face || k < 0 || fv[(k + 1) % per_face] != a[j] ||
                fv[(k + per_face - 1) % per_face] != a[(j + 1) % n_a]) {
                set_error(error, error_len, "a ring face is not (O, a_j, [b_j,] a_{j+1}) in order");
                return 3;
            }
            if (per_face == 4) ring.push_back(fv[(k + 2) % 4]);
        }
        if (l == level) return 0;
        int o_next = topo.GetVertexChildVertex(o);
        Far::TopologyLevel const &child = refiner.GetLevel(l + 1);
        for (int i = 0; i < n_a; ++i) {
            Far::Index e = topo.FindEdge(o, a[i]);
            if (e < 0) {
                set_error(error, error_len, "a_i is not an edge neighbour of O");
                return 4;
            }
            a[i] = topo.GetEdgeChildVertex(e);
        }
        for (int j = 0; j < n_f; ++j) {
            Far::ConstIndexArray kids = topo.GetFaceChildFaces(faces[j]);
            int found = -1;
            for (int m = 0; m < kids.size(); ++m) {
                if (face_has(child, kids[m], o_next)) found = kids[m];
            }
            if (found < 0) {
                set_error(error, error_len, "no child face at the central vertex");
                return 5;
            }
            faces[j] = found;
        }
        o = o_next;
    }
}

// Unit vectors e_c at the ring's vertices of a level (r = ring size) and e_r at every other vertex.
std::vector<Vec> unit_vectors(int n_level_vertices, std::vector<int> const &ring) {
    std::vector<Vec> values(static_cast<size_t>(n_level_vertices));
    const int r = static_cast<int>(ring.size());
    for (Vec &v : values) {
        v.Clear();
        v.p[r] = 1.0;
    }
    for (int c = 0; c < r; ++c) {
        values[ring[c]].p[r] = 0.0;
        values[ring[c]].p[c] = 1.0;
    }
    return values;
}

}  // namespace

extern "C" {

// The one-step matrix of a vertex's ring at refinement level `level` of a tagged mesh, and the
// limit masks (position, first and second derivative) of the vertex at that level.
// The ring is (O, a_0..a_{n_a-1}, b_0..b_{n_f-1}) on quads, (O, a_0..a_{n_a-1}) on triangles (n_f
// faces given all the same), r its size (r + 1 <= 64). matrix_out (r x (r + 1), row-major): row i
// is ring point i at level + 1 as weights of the ring points at `level`, the last column the total
// weight on every vertex outside the ring (zero when the ring is closed under refinement);
// limit_out (3 x (r + 1)) the three limit masks in the same columns. Returns 0 on success.
int symdecomp_osd_sharp_ring(const int *options, int per_face, int n_vertices, int n_faces, const int *face_vertices,
                             int n_creases, const int *crease_pairs, const float *crease_weights, int n_corners,
                             const int *corner_vertices, const float *corner_weights, int center, int n_a,
                             const int *ring_a, int n_f, const int *ring_faces, int level, double *matrix_out,
                             double *limit_out, char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        const int r = 1 + n_a + (per_face == 4 ? n_f : 0);
        if (n_vertices <= 0 || n_faces <= 0 || n_a < 1 || n_f < 1 || level < 0 || r + 1 > kDim) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        SharpTags tags{n_creases, crease_pairs, crease_weights, n_corners, corner_vertices, corner_weights};
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_sharp_refiner(options, per_face, n_vertices, n_faces, face_vertices, tags, error, error_len);
        std::unique_ptr<Far::TopologyRefiner> limiter =
            make_sharp_refiner(options, per_face, n_vertices, n_faces, face_vertices, tags, error, error_len);
        if (!refiner || !limiter) return 2;
        Far::TopologyRefiner::UniformOptions uniform(level + 1);
        uniform.fullTopologyInLastLevel = true;
        refiner->RefineUniform(uniform);
        Far::TopologyRefiner::UniformOptions to_level(level);
        to_level.fullTopologyInLastLevel = true;
        limiter->RefineUniform(to_level);
        std::vector<int> ring, next, ring_limit;
        int code = follow_ring(*refiner, per_face, center, n_a, ring_a, n_f, ring_faces, level, ring, error, error_len);
        if (!code) code = follow_ring(*refiner, per_face, center, n_a, ring_a, n_f, ring_faces, level + 1, next, error, error_len);
        if (!code) code = follow_ring(*limiter, per_face, center, n_a, ring_a, n_f, ring_faces, level, ring_limit, error, error_len);
        if (code) return code;

        std::vector<Vec> src = unit_vectors(refiner->GetLevel(level).GetNumVertices(), ring);
        std::vector<Vec> dst(static_cast<size_t>(refiner->GetLevel(level + 1).GetNumVertices()));
        Vec *dst_start = dst.data();
        Far::PrimvarRefinerReal<double>(*refiner).Interpolate(level + 1, src.data(), dst_start);
        for (int i = 0; i < r; ++i) {
            for (int c = 0; c <= r; ++c) matrix_out[i * (r + 1) + c] = dst[next[i]].p[c];
        }

        std::vector<Vec> at = unit_vectors(limiter->GetLevel(level).GetNumVertices(), ring_limit);
        std::vector<Vec> pos(at.size()), du(at.size()), dv(at.size());
        Vec *pos_dst = pos.data(), *du_dst = du.data(), *dv_dst = dv.data();
        Far::PrimvarRefinerReal<double>(*limiter).Limit(at.data(), pos_dst, du_dst, dv_dst);
        if (osd_error(error, error_len)) return 6;
        const int o = ring_limit[0];
        for (int c = 0; c <= r; ++c) {
            limit_out[c] = pos[o].p[c];
            limit_out[(r + 1) + c] = du[o].p[c];
            limit_out[2 * (r + 1) + c] = dv[o].p[c];
        }
        return 0;
    });
}

// Limit positions and first derivatives at n_points parameters (face, u, v) of a tagged mesh,
// by OpenSubdiv's patch table (feature-adaptive refinement to `isolation`, infinitely sharp
// patches, Gregory end caps, double precision) and its patch map. out: 9 doubles per point
// (position, d/du, d/dv). Returns 0 on success, 8 when a parameter lies in no patch.
int symdecomp_osd_sharp_patch_points(const int *options, int per_face, int n_vertices, int n_faces,
                                     const int *face_vertices, const double *positions, int n_creases,
                                     const int *crease_pairs, const float *crease_weights, int n_corners,
                                     const int *corner_vertices, const float *corner_weights, int isolation,
                                     int n_points, const int *point_faces, const double *uv, double *out,
                                     char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        if (n_vertices <= 0 || n_faces <= 0 || n_points < 0 || isolation < 1 || isolation > 10) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        SharpTags tags{n_creases, crease_pairs, crease_weights, n_corners, corner_vertices, corner_weights};
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_sharp_refiner(options, per_face, n_vertices, n_faces, face_vertices, tags, error, error_len);
        if (!refiner) return 2;
        Far::PatchTableFactory::Options patch_options(isolation);
        patch_options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
        patch_options.useInfSharpPatch = true;
        patch_options.generateLegacySharpCornerPatches = false;
        patch_options.SetPatchPrecision<double>();
        refiner->RefineAdaptive(patch_options.GetRefineAdaptiveOptions());
        std::unique_ptr<Far::PatchTable> table(Far::PatchTableFactory::Create(*refiner, patch_options));
        if (!table || osd_error(error, error_len)) return table ? 6 : 2;
        const int refined = refiner->GetNumVerticesTotal();
        std::vector<Point> points(static_cast<size_t>(refined + table->GetNumLocalPoints()));
        for (int v = 0; v < n_vertices; ++v) {
            for (int c = 0; c < 3; ++c) points[v].p[c] = positions[3 * v + c];
        }
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        Point *src = points.data();
        for (int level = 1; level <= refiner->GetMaxLevel(); ++level) {
            Point *dst = src + refiner->GetLevel(level - 1).GetNumVertices();
            primvar.Interpolate(level, src, dst);
            src = dst;
        }
        if (table->GetNumLocalPoints()) {  // the end caps' points, from the double-precision stencils
            Far::StencilTableReal<double> const *local = table->GetLocalPointStencilTable<double>();
            if (!local) {
                set_error(error, error_len, "the patch table has no double-precision local point stencils");
                return 6;
            }
            local->UpdateValues(points.data(), points.data() + refined);
        }
        Far::PatchMap map(*table);
        double w[20], wu[20], wv[20];
        for (int q = 0; q < n_points; ++q) {
            Far::PatchTable::PatchHandle const *handle = map.FindPatch(point_faces[q], uv[2 * q], uv[2 * q + 1]);
            if (!handle) {
                set_error(error, error_len, "a (face, u, v) parameter lies in no patch");
                return 8;
            }
            table->EvaluateBasis(*handle, uv[2 * q], uv[2 * q + 1], w, wu, wv);
            Far::ConstIndexArray cvs = table->GetPatchVertices(*handle);
            double *o = out + 9 * q;
            for (int c = 0; c < 9; ++c) o[c] = 0.0;
            for (int m = 0; m < cvs.size(); ++m) {
                for (int c = 0; c < 3; ++c) {
                    o[c] += w[m] * points[cvs[m]].p[c];
                    o[3 + c] += wu[m] * points[cvs[m]].p[c];
                    o[6 + c] += wv[m] * points[cvs[m]].p[c];
                }
            }
        }
        return 0;
    });
}

}  // extern "C"

// ---------------------------------------------------------------------------------------------
// Limit frames of every base vertex of a whole tagged mesh (oracle --mesh): the mesh is refined
// uniformly `levels` times (enough for every semi-sharp crease to have decayed), and the limit
// position and first derivatives of each base vertex are OpenSubdiv's limit masks
// (Far::PrimvarRefiner::Limit) at its descendant vertex on the last level, 3 doubles each.

extern "C" {

int symdecomp_osd_tagged_limit_frames(const int *options, int per_face, int n_vertices, int n_faces,
                                      const int *face_vertices, const double *positions, int n_creases,
                                      const int *crease_pairs, const float *crease_weights, int n_corners,
                                      const int *corner_vertices, const float *corner_weights, int levels,
                                      double *limits_out, double *du_out, double *dv_out, char *error, int error_len) {
    return guarded(error, error_len, [&]() -> int {
        if (n_vertices <= 0 || n_faces <= 0 || levels < 0 || levels > 10) {
            set_error(error, error_len, "bad sizes");
            return 1;
        }
        SharpTags tags{n_creases, crease_pairs, crease_weights, n_corners, corner_vertices, corner_weights};
        std::unique_ptr<Far::TopologyRefiner> refiner =
            make_sharp_refiner(options, per_face, n_vertices, n_faces, face_vertices, tags, error, error_len);
        if (!refiner) return 2;
        if (levels > 0) {
            Far::TopologyRefiner::UniformOptions uniform(levels);
            uniform.fullTopologyInLastLevel = true;
            refiner->RefineUniform(uniform);
        }
        if (osd_error(error, error_len)) return 6;
        std::vector<Point> buffer = base_points(*refiner, n_vertices, positions);
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        std::vector<Point *> start = interpolate(*refiner, primvar, buffer, levels);
        const int last = refiner->GetLevel(levels).GetNumVertices();
        std::vector<Point> limit(static_cast<size_t>(last)), du(limit.size()), dv(limit.size());
        Point *limit_dst = limit.data(), *du_dst = du.data(), *dv_dst = dv.data();
        primvar.Limit(start[levels], limit_dst, du_dst, dv_dst);
        if (osd_error(error, error_len)) return 6;
        for (int v = 0; v < n_vertices; ++v) {
            int at = v;
            for (int level = 0; level < levels; ++level) at = refiner->GetLevel(level).GetVertexChildVertex(at);
            if (at < 0) {
                set_error(error, error_len, "a base vertex has no descendant on the last level");
                return 7;
            }
            for (int c = 0; c < 3; ++c) {
                limits_out[3 * v + c] = limit[at].p[c];
                du_out[3 * v + c] = du[at].p[c];
                dv_out[3 * v + c] = dv[at].p[c];
            }
        }
        return 0;
    });
}

}  // extern "C"
