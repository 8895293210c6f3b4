// remesh_cgal.cpp - isotropic remeshing of spheres and imported meshes
// (remesh.h). With mesh2d_cgal.cpp, one of the two files that include CGAL;
// no exception crosses the C API.
#include "solver/geometry/remesh.h"
#include "base/error_report.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <map>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
namespace PMP = CGAL::Polygon_mesh_processing;

// Passes of split / collapse / flip / relax: three are CGAL's examples'
// choice, and the sizes settle within them.
const unsigned REMESH_PASSES = 3;

cdl_status fail(cdl_error *err, cdl_status st, const char *what)
{
    cdl_error_set(err, st, "remeshing failed: %s", what);
    return st;
}

// The mesh as plain arrays, vertices in the mesh's order.
cdl_status export_mesh(const Mesh &mesh, cdl_trimesh *out, cdl_error *err)
{
    std::map<vertex_descriptor, uint32_t> index;
    size_t nv = mesh.number_of_vertices(), nt = mesh.number_of_faces();
    out->xyz = (double *)std::malloc((nv ? nv : 1) * 3 * sizeof(double));
    out->triangles = (uint32_t *)std::malloc((nt ? nt : 1) * 3 * sizeof(uint32_t));
    if (!out->xyz || !out->triangles) {
        cdl_trimesh_release(out);
        return cdl_error_out_of_memory(err);
    }
    uint32_t k = 0;
    for (vertex_descriptor v : mesh.vertices()) {
        const Point &p = mesh.point(v);
        out->xyz[3 * k] = p.x();
        out->xyz[3 * k + 1] = p.y();
        out->xyz[3 * k + 2] = p.z();
        index[v] = k++;
    }
    size_t t = 0;
    for (Mesh::Face_index f : mesh.faces()) {
        int i = 0;
        for (vertex_descriptor v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            if (i < 3) out->triangles[3 * t + i] = index[v];
            ++i;
        }
        if (i != 3) {
            cdl_trimesh_release(out);
            return fail(err, CDL_ERR_INTERNAL, "a face that is not a triangle");
        }
        ++t;
    }
    out->vertex_count = nv;
    out->triangle_count = nt;
    return CDL_OK;
}

Point on_sphere(const Point &p, const Point &c, double r)
{
    K::Vector_3 d = p - c;
    double len = std::sqrt(d.squared_length());
    if (!(len > 0.0)) return Point(c.x(), c.y(), c.z() + r);
    return c + d * (r / len);
}

// Moves a vertex onto the sphere (isotropic_remeshing's projection_functor).
struct Sphere_projection {
    const Mesh *mesh;
    Point center;
    double radius;
    Point operator()(vertex_descriptor v) const { return on_sphere(mesh->point(v), center, radius); }
};

// The icosahedron's 12 vertices (0, +-1, +-phi) cyclically and its 20
// faces, counter-clockwise seen from outside.
void icosahedron(std::vector<Point> &points, std::vector<std::array<size_t, 3>> &faces)
{
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    const double v[12][3] = {{-1, phi, 0}, {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
                             {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
    const size_t f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                             {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto &p : v) points.push_back(Point(p[0], p[1], p[2]));
    for (auto &t : f) faces.push_back({t[0], t[1], t[2]});
}

// Split every triangle in four at its edges' midpoints, each midpoint
// projected onto the unit sphere.
void subdivide(std::vector<Point> &points, std::vector<std::array<size_t, 3>> &faces)
{
    std::map<std::pair<size_t, size_t>, size_t> mid;
    auto midpoint = [&](size_t a, size_t b) {
        std::pair<size_t, size_t> key(std::min(a, b), std::max(a, b));
        auto it = mid.find(key);
        if (it != mid.end()) return it->second;
        Point m = on_sphere(CGAL::midpoint(points[a], points[b]), CGAL::ORIGIN, 1.0);
        points.push_back(m);
        mid[key] = points.size() - 1;
        return points.size() - 1;
    };
    std::vector<std::array<size_t, 3>> next;
    for (auto &t : faces) {
        size_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
        next.push_back({t[0], ab, ca});
        next.push_back({ab, t[1], bc});
        next.push_back({ca, bc, t[2]});
        next.push_back({ab, bc, ca});
    }
    faces.swap(next);
}

template <class Body> cdl_status guarded(cdl_trimesh *out, cdl_error *err, Body body)
{
    try {
        return body();
    } catch (const std::exception &e) {
        cdl_trimesh_release(out);
        return fail(err, CDL_ERR_INTERNAL, e.what());
    } catch (...) {
        cdl_trimesh_release(out);
        return fail(err, CDL_ERR_INTERNAL, "unknown exception");
    }
}

} // namespace

extern "C" void cdl_trimesh_release(cdl_trimesh *mesh)
{
    if (!mesh) return;
    std::free(mesh->xyz);
    std::free(mesh->triangles);
    mesh->xyz = nullptr;
    mesh->triangles = nullptr;
    mesh->vertex_count = mesh->triangle_count = 0;
}

extern "C" cdl_status cdl_remesh_sphere(const double center[3], double radius, int inward, double target_edge,
                                        cdl_trimesh *out, cdl_error *err)
{
    *out = cdl_trimesh{nullptr, 0, nullptr, 0};
    if (!(radius > 0.0) || !std::isfinite(radius)) return fail(err, CDL_ERR_INPUT, "the radius must be positive");
    if (!(target_edge > 0.0)) return fail(err, CDL_ERR_INPUT, "the target edge must be positive");
    return guarded(out, err, [&]() -> cdl_status {
        // The unit icosahedron's edge is 1.05; split while the sphere's
        // edges are above twice the target (the remeshing does the rest).
        std::vector<Point> unit;
        std::vector<std::array<size_t, 3>> tris;
        icosahedron(unit, tris);
        for (Point &p : unit) p = on_sphere(p, CGAL::ORIGIN, 1.0);
        double edge = 1.0515 * radius;
        while (edge > 2.0 * target_edge && tris.size() < (1u << 22)) {
            subdivide(unit, tris);
            edge *= 0.5;
        }
        Point c(center[0], center[1], center[2]);
        Mesh mesh;
        std::vector<vertex_descriptor> vd;
        for (const Point &p : unit) vd.push_back(mesh.add_vertex(c + (p - CGAL::ORIGIN) * radius));
        for (auto &t : tris) mesh.add_face(vd[t[0]], vd[t[1]], vd[t[2]]);
        Sphere_projection project{&mesh, c, radius};
        PMP::isotropic_remeshing(faces(mesh), target_edge, mesh,
                                 CGAL::parameters::number_of_iterations(REMESH_PASSES).projection_functor(project));
        mesh.collect_garbage();
        for (vertex_descriptor v : mesh.vertices()) mesh.point(v) = on_sphere(mesh.point(v), c, radius);
        if (inward) PMP::reverse_face_orientations(mesh);
        return export_mesh(mesh, out, err);
    });
}

extern "C" cdl_status cdl_remesh_triangles(const double *xyz, size_t vertex_count, const uint32_t *triangles,
                                           size_t triangle_count, double target_edge, double feature_angle_deg,
                                           cdl_trimesh *out, cdl_error *err)
{
    *out = cdl_trimesh{nullptr, 0, nullptr, 0};
    if (!(target_edge > 0.0)) return fail(err, CDL_ERR_INPUT, "the target edge must be positive");
    return guarded(out, err, [&]() -> cdl_status {
        std::vector<Point> points;
        std::vector<std::vector<size_t>> polygons;
        for (size_t v = 0; v < vertex_count; ++v) points.push_back(Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
        for (size_t t = 0; t < triangle_count; ++t) {
            const uint32_t *tri = &triangles[3 * t];
            if (tri[0] >= vertex_count || tri[1] >= vertex_count || tri[2] >= vertex_count)
                return fail(err, CDL_ERR_INPUT, "a triangle names a vertex that does not exist");
            polygons.push_back({tri[0], tri[1], tri[2]});
        }
        if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
            return fail(err, CDL_ERR_INPUT,
                        "not a manifold surface (an edge shared by more than two triangles, two sheets meeting at "
                        "a vertex, or neighbours of opposite orientation)");
        Mesh mesh;
        PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
        // Sharp edges and borders: split to the target, then held.
        Mesh::Property_map<edge_descriptor, bool> held =
            mesh.add_property_map<edge_descriptor, bool>("e:held", false).first;
        PMP::detect_sharp_edges(mesh, feature_angle_deg, held);
        std::vector<edge_descriptor> kept;
        for (edge_descriptor e : mesh.edges()) {
            if (mesh.is_border(e)) put(held, e, true);
            if (get(held, e)) kept.push_back(e);
        }
        PMP::split_long_edges(kept, target_edge, mesh, CGAL::parameters::edge_is_constrained_map(held));
        PMP::isotropic_remeshing(faces(mesh), target_edge, mesh,
                                 CGAL::parameters::number_of_iterations(REMESH_PASSES)
                                     .edge_is_constrained_map(held)
                                     .protect_constraints(true));
        mesh.collect_garbage();
        return export_mesh(mesh, out, err);
    });
}
