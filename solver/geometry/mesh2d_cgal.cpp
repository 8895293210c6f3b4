// mesh2d_cgal.cpp - one of the two files that include CGAL (with remesh_cgal.cpp). It exposes the C API of
// mesh2d.h and never lets an exception cross it.
#include "base/error_report.h"
#include "solver/geometry/mesh2d.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <list>
#include <map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
// Vertex info: its number in a cdl_cdt2d (-1 until numbered).
struct Vertex_number {
    long id = -1;
};
typedef CGAL::Triangulation_vertex_base_with_info_2<Vertex_number, K> Vbi;
typedef CGAL::Delaunay_mesh_vertex_base_2<K, Vbi> Vb;
// Face info: nesting depth (number of constrained rings crossed from outside).
typedef CGAL::Delaunay_mesh_face_base_2<K> Fbm;
typedef CGAL::Triangulation_face_base_with_info_2<int, K, Fbm> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Exact_predicates_tag Itag;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, Itag> CDT;
typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Criteria;
typedef CDT::Point Point;

void insert_ring(CDT &cdt, const cdl_ring2d &ring)
{
    std::vector<CDT::Vertex_handle> vh;
    vh.reserve(ring.count);
    for (size_t i = 0; i < ring.count; ++i)
        vh.push_back(cdt.insert(Point(ring.xy[2 * i], ring.xy[2 * i + 1])));
    for (size_t i = 0; i < ring.count; ++i) {
        CDT::Vertex_handle a = vh[i], b = vh[(i + 1) % ring.count];
        if (a != b) cdt.insert_constraint(a, b);
    }
}

// Breadth-first flood fill from the infinite face: crossing a constrained
// edge increases the depth by one. Odd depth = inside the polygon.
void mark_depths(CDT &cdt)
{
    for (CDT::All_faces_iterator f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::list<CDT::Face_handle> frontier;
    cdt.infinite_face()->info() = 0;
    frontier.push_back(cdt.infinite_face());
    std::list<CDT::Face_handle> next_level;
    int depth = 0;
    while (!frontier.empty()) {
        while (!frontier.empty()) {
            CDT::Face_handle f = frontier.front();
            frontier.pop_front();
            for (int i = 0; i < 3; ++i) {
                CDT::Face_handle n = f->neighbor(i);
                if (n->info() != -1) continue;
                if (cdt.is_constrained(CDT::Edge(f, i))) {
                    next_level.push_back(n);
                } else {
                    n->info() = depth;
                    frontier.push_back(n);
                }
            }
        }
        ++depth;
        for (CDT::Face_handle n : next_level) {
            if (n->info() == -1) {
                n->info() = depth;
                frontier.push_back(n);
            }
        }
        next_level.clear();
    }
}

int fail(cdl_error *err, cdl_status st, const char *what)
{
    cdl_error_set(err, st, "polygon triangulation failed: %s", what);
    return st;
}

} // namespace

extern "C" cdl_status cdl_mesh2d_triangulate(cdl_ring2d outer, const cdl_ring2d *holes, size_t hole_count,
                                             double max_edge, cdl_mesh2d *out, cdl_error *err)
{
    return cdl_mesh2d_triangulate_bounded(outer, holes, hole_count, max_edge, SIZE_MAX, out, err);
}

extern "C" cdl_status cdl_mesh2d_triangulate_bounded(cdl_ring2d outer, const cdl_ring2d *holes, size_t hole_count,
                                                     double max_edge, size_t max_vertices, cdl_mesh2d *out,
                                                     cdl_error *err)
{
    out->xy = nullptr;
    out->triangles = nullptr;
    out->vertex_count = out->triangle_count = 0;
    out->area = 0.0;
    if (outer.count < 3) return (cdl_status)fail(err, CDL_ERR_INPUT, "the outer ring needs at least 3 points");
    for (size_t h = 0; h < hole_count; ++h)
        if (holes[h].count < 3) return (cdl_status)fail(err, CDL_ERR_INPUT, "a hole needs at least 3 points");
    try {
        CDT cdt;
        insert_ring(cdt, outer);
        for (size_t h = 0; h < hole_count; ++h) insert_ring(cdt, holes[h]);
        if (cdt.dimension() < 2)
            return (cdl_status)fail(err, CDL_ERR_INPUT, "the polygon has no area (its points are collinear)");
        if (max_edge > 0.0) {
            // Refine every bounded face; the parity marking below drops holes.
            // Step by step, so that a runaway refinement can be stopped.
            CGAL::Delaunay_mesher_2<CDT, Criteria> mesher(cdt, Criteria(0.125, max_edge));
            mesher.init(false);
            while (mesher.step_by_step_refine_mesh())
                if (cdt.number_of_vertices() > max_vertices)
                    return (cdl_status)fail(err, CDL_ERR_INPUT,
                                            "the mesh needs more points than allowed (is a vertex almost on an "
                                            "edge, or an edge far shorter than the spacing?)");
        }
        mark_depths(cdt);

        std::map<CDT::Vertex_handle, uint32_t> index;
        std::vector<double> xy;
        std::vector<uint32_t> tri;
        double area = 0.0;
        for (CDT::Finite_faces_iterator f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (f->info() % 2 != 1) continue;
            uint32_t ids[3];
            for (int i = 0; i < 3; ++i) {
                CDT::Vertex_handle v = f->vertex(i);
                auto it = index.find(v);
                if (it == index.end()) {
                    uint32_t id = (uint32_t)(xy.size() / 2);
                    index.emplace(v, id);
                    xy.push_back(v->point().x());
                    xy.push_back(v->point().y());
                    ids[i] = id;
                } else {
                    ids[i] = it->second;
                }
            }
            // CGAL faces are counter-clockwise.
            tri.insert(tri.end(), ids, ids + 3);
            area += std::fabs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
        }
        if (tri.empty()) return (cdl_status)fail(err, CDL_ERR_INPUT, "the polygon has no area");

        out->xy = (double *)std::malloc(xy.size() * sizeof(double));
        out->triangles = (uint32_t *)std::malloc(tri.size() * sizeof(uint32_t));
        if (!out->xy || !out->triangles) {
            cdl_mesh2d_release(out);
            return cdl_error_out_of_memory(err);
        }
        std::copy(xy.begin(), xy.end(), out->xy);
        std::copy(tri.begin(), tri.end(), out->triangles);
        out->vertex_count = xy.size() / 2;
        out->triangle_count = tri.size() / 3;
        out->area = area;
        return CDL_OK;
    } catch (const std::exception &e) {
        cdl_mesh2d_release(out);
        return (cdl_status)fail(err, CDL_ERR_INTERNAL, e.what());
    } catch (...) {
        cdl_mesh2d_release(out);
        return (cdl_status)fail(err, CDL_ERR_INTERNAL, "unknown exception");
    }
}

extern "C" void cdl_mesh2d_release(cdl_mesh2d *mesh)
{
    if (!mesh) return;
    std::free(mesh->xy);
    std::free(mesh->triangles);
    mesh->xy = nullptr;
    mesh->triangles = nullptr;
    mesh->vertex_count = mesh->triangle_count = 0;
}

// ---- cdl_cdt2d: a mesh that keeps refining (mesh2d.h) ------------------------

struct cdl_cdt2d {
    CDT cdt;
    std::vector<CDT::Vertex_handle> by_id;  // vertex number -> handle
};

namespace {

// Number the vertices that have no number yet, in the triangulation's own
// (deterministic) order.
void number_new_vertices(cdl_cdt2d &m)
{
    for (CDT::Finite_vertices_iterator v = m.cdt.finite_vertices_begin(); v != m.cdt.finite_vertices_end(); ++v)
        if (v->info().id < 0) {
            v->info().id = (long)m.by_id.size();
            m.by_id.push_back(v);
        }
}

// The domain: faces of odd nesting depth, also as the mesher's in_domain flag.
void mark_domain(CDT &cdt)
{
    mark_depths(cdt);
    for (CDT::All_faces_iterator f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
        f->set_in_domain(!cdt.is_infinite(f) && f->info() % 2 == 1);
}

// Delaunay refinement of the domain to the shape bound and max_edge.
cdl_status refine_domain(cdl_cdt2d &m, double max_edge, size_t max_vertices, cdl_error *err)
{
    mark_domain(m.cdt);
    CGAL::Delaunay_mesher_2<CDT, Criteria> mesher(m.cdt, Criteria(0.125, max_edge));
    mesher.init(true);
    while (mesher.step_by_step_refine_mesh())
        if (m.cdt.number_of_vertices() > max_vertices)
            return (cdl_status)fail(err, CDL_ERR_INPUT,
                                    "the mesh needs more points than allowed (is a vertex almost on an edge, or an "
                                    "edge far shorter than the spacing?)");
    mark_domain(m.cdt);
    number_new_vertices(m);
    return CDL_OK;
}

double squared_distance_to_segment(const Point &p, const Point &a, const Point &b, double *t_out)
{
    double dx = b.x() - a.x(), dy = b.y() - a.y(), len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2 : 0.0;
    *t_out = t;
    t = std::max(0.0, std::min(1.0, t));
    double ex = p.x() - (a.x() + t * dx), ey = p.y() - (a.y() + t * dy);
    return ex * ex + ey * ey;
}

// Is p within `tolerance` of the constrained edge e, projecting inside it?
// *distance2 its squared distance; *at_end when it is within tolerance of
// an end (then it is that vertex, not a new one).
bool near_constrained_edge(const CDT &cdt, const CDT::Edge &e, const Point &p, double tolerance, double *distance2,
                           bool *at_end)
{
    if (!cdt.is_constrained(e)) return false;
    CDT::Vertex_handle a = e.first->vertex(CDT::ccw(e.second)), b = e.first->vertex(CDT::cw(e.second));
    if (cdt.is_infinite(a) || cdt.is_infinite(b)) return false;
    double t;
    *distance2 = squared_distance_to_segment(p, a->point(), b->point(), &t);
    if (*distance2 > tolerance * tolerance) return false;
    double tol2 = tolerance * tolerance;
    *at_end = CGAL::squared_distance(p, a->point()) <= tol2 || CGAL::squared_distance(p, b->point()) <= tol2;
    return *at_end || (t > 0.0 && t < 1.0);
}

// The constrained edge nearest p, within `tolerance`: among the edges of f
// and its neighbours, else (a point just outside the convex hull, located
// in any infinite face whose edge's line it is beyond) among all. False when
// there is none or p is at one of its ends.
bool find_constrained_edge(const CDT &cdt, CDT::Face_handle f, const Point &p, double tolerance, CDT::Edge *out)
{
    CDT::Face_handle faces[4] = {f, f->neighbor(0), f->neighbor(1), f->neighbor(2)};
    double best = INFINITY, d2;
    bool found = false, at_end = false, end;
    for (CDT::Face_handle g : faces)
        for (int i = 0; i < 3; ++i)
            if (near_constrained_edge(cdt, CDT::Edge(g, i), p, tolerance, &d2, &end) && d2 < best) {
                best = d2;
                *out = CDT::Edge(g, i);
                found = true;
                at_end = end;
            }
    if (!found)
        for (CDT::Constrained_edges_iterator e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e)
            if (near_constrained_edge(cdt, *e, p, tolerance, &d2, &end) && d2 < best) {
                best = d2;
                *out = *e;
                found = true;
                at_end = end;
            }
    return found && !at_end;
}

// Where a point is in the triangulation.
struct Location {
    Point point;
    CDT::Locate_type type;
    int index;
    CDT::Face_handle face;
};

Location locate(const CDT &cdt, const double *xy)
{
    Location l{Point(xy[0], xy[1]), CDT::VERTEX, 0, CDT::Face_handle()};
    l.face = cdt.locate(l.point, l.type, l.index);
    return l;
}

template <class Body> cdl_status guarded(cdl_error *err, Body body)
{
    try {
        return body();
    } catch (const std::exception &e) {
        return (cdl_status)fail(err, CDL_ERR_INTERNAL, e.what());
    } catch (...) {
        return (cdl_status)fail(err, CDL_ERR_INTERNAL, "unknown exception");
    }
}

} // namespace

extern "C" cdl_status cdl_cdt2d_create(cdl_ring2d outer, const cdl_ring2d *holes, size_t hole_count,
                                       double max_edge, size_t max_vertices, cdl_cdt2d **out, cdl_error *err)
{
    *out = nullptr;
    if (outer.count < 3) return (cdl_status)fail(err, CDL_ERR_INPUT, "the outer ring needs at least 3 points");
    for (size_t h = 0; h < hole_count; ++h)
        if (holes[h].count < 3) return (cdl_status)fail(err, CDL_ERR_INPUT, "a hole needs at least 3 points");
    if (!(max_edge > 0.0)) return (cdl_status)fail(err, CDL_ERR_INPUT, "the largest edge must be positive");
    cdl_cdt2d *m = nullptr;
    cdl_status st = guarded(err, [&]() -> cdl_status {
        m = new cdl_cdt2d();
        insert_ring(m->cdt, outer);
        for (size_t h = 0; h < hole_count; ++h) insert_ring(m->cdt, holes[h]);
        if (m->cdt.dimension() < 2)
            return (cdl_status)fail(err, CDL_ERR_INPUT, "the polygon has no area (its points are collinear)");
        number_new_vertices(*m);
        return refine_domain(*m, max_edge, max_vertices, err);
    });
    if (st != CDL_OK) {
        delete m;
        return st;
    }
    *out = m;
    return CDL_OK;
}

extern "C" void cdl_cdt2d_release(cdl_cdt2d *mesh)
{
    delete mesh;
}

extern "C" size_t cdl_cdt2d_vertex_count(const cdl_cdt2d *mesh)
{
    return mesh->by_id.size();
}

extern "C" void cdl_cdt2d_vertex(const cdl_cdt2d *mesh, size_t id, double xy[2], int *on_boundary)
{
    CDT::Vertex_handle v = mesh->by_id[id];
    xy[0] = v->point().x();
    xy[1] = v->point().y();
    if (on_boundary) on_boundary[0] = mesh->cdt.are_there_incident_constraints(v) ? 1 : 0;
}

extern "C" cdl_status cdl_cdt2d_triangles(const cdl_cdt2d *mesh, uint32_t **triangles, size_t *triangle_count,
                                          cdl_error *err)
{
    *triangles = nullptr;
    *triangle_count = 0;
    size_t n = 0;
    for (CDT::Finite_faces_iterator f = mesh->cdt.finite_faces_begin(); f != mesh->cdt.finite_faces_end(); ++f)
        if (f->is_in_domain()) ++n;
    uint32_t *tri = (uint32_t *)std::malloc((n ? n : 1) * 3 * sizeof *tri);
    if (!tri) return cdl_error_out_of_memory(err);
    size_t k = 0;
    for (CDT::Finite_faces_iterator f = mesh->cdt.finite_faces_begin(); f != mesh->cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        for (int i = 0; i < 3; ++i) tri[3 * k + i] = (uint32_t)f->vertex(i)->info().id;
        ++k;
    }
    *triangles = tri;
    *triangle_count = n;
    return CDL_OK;
}

extern "C" cdl_status cdl_cdt2d_split_edges(cdl_cdt2d *mesh, const uint32_t *ab, const double *xy, size_t count,
                                            size_t *new_id, cdl_error *err)
{
    return guarded(err, [&]() -> cdl_status {
        for (size_t k = 0; k < count; ++k) {
            new_id[k] = SIZE_MAX;
            CDT::Face_handle f;
            int i;
            if (!mesh->cdt.is_edge(mesh->by_id[ab[2 * k]], mesh->by_id[ab[2 * k + 1]], f, i)) continue;
            Point p(xy[2 * k], xy[2 * k + 1]);
            // A constrained edge is split where it is (the point may be off
            // its line by a rounding); an interior one by locating the point.
            CDT::Vertex_handle v = mesh->cdt.is_constrained(CDT::Edge(f, i)) ? mesh->cdt.insert(p, CDT::EDGE, f, i)
                                                                             : mesh->cdt.insert(p, f);
            if (v->info().id < 0) {
                v->info().id = (long)mesh->by_id.size();
                mesh->by_id.push_back(v);
            }
            new_id[k] = (size_t)v->info().id;
        }
        mark_domain(mesh->cdt);
        number_new_vertices(*mesh);
        return CDL_OK;
    });
}

extern "C" cdl_status cdl_cdt2d_insert_on_boundary(cdl_cdt2d *mesh, const double *xy, size_t count,
                                                   double tolerance, size_t *inserted, cdl_error *err)
{
    *inserted = 0;
    return guarded(err, [&]() -> cdl_status {
        for (size_t k = 0; k < count; ++k) {
            Location l = locate(mesh->cdt, &xy[2 * k]);
            if (l.type == CDT::VERTEX || l.type == CDT::OUTSIDE_AFFINE_HULL) continue;
            CDT::Edge e;
            if (!find_constrained_edge(mesh->cdt, l.face, l.point, tolerance, &e)) continue;
            CDT::Vertex_handle v = mesh->cdt.insert(l.point, CDT::EDGE, e.first, e.second);
            v->info().id = (long)mesh->by_id.size();
            mesh->by_id.push_back(v);
            ++*inserted;
        }
        mark_domain(mesh->cdt);
        return CDL_OK;
    });
}

extern "C" cdl_status cdl_cdt2d_insert_inside(cdl_cdt2d *mesh, const double *xy, size_t count, size_t *inserted,
                                              cdl_error *err)
{
    *inserted = 0;
    return guarded(err, [&]() -> cdl_status {
        for (size_t k = 0; k < count; ++k) {
            Location l = locate(mesh->cdt, &xy[2 * k]);
            if (l.type == CDT::FACE) {
                if (!l.face->is_in_domain()) continue;
            } else if (l.type == CDT::EDGE) {
                if (mesh->cdt.is_constrained(CDT::Edge(l.face, l.index)) || !l.face->is_in_domain() ||
                    !l.face->neighbor(l.index)->is_in_domain())
                    continue;
            } else {
                continue;
            }
            CDT::Vertex_handle v = mesh->cdt.insert(l.point, l.type, l.face, l.index);
            v->info().id = (long)mesh->by_id.size();
            mesh->by_id.push_back(v);
            ++*inserted;
            mark_domain(mesh->cdt);
        }
        number_new_vertices(*mesh);
        return CDL_OK;
    });
}

extern "C" cdl_status cdl_cdt2d_improve(cdl_cdt2d *mesh, double max_edge, size_t max_vertices, cdl_error *err)
{
    return guarded(err, [&]() -> cdl_status { return refine_domain(*mesh, max_edge, max_vertices, err); });
}
