// mesh2d_cgal.cpp - the only file that includes CGAL. It exposes the C API of
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

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <list>
#include <map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_mesh_vertex_base_2<K> Vb;
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
