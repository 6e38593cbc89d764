// Region and crossing queries per second for each kind of domain, on one core (a loop of
// single queries) and on all cores (the batch versions). Points are uniform in the domain's
// bounds grown by 5%; segments are mesher-like: a random point and a random direction, of
// length 1/64 of the bounds' diagonal (an octree edge a few levels down).
//   bench_domain_queries CGAL_DATA SDF_GRID.rawiv   -> one Markdown table on stdout
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/image.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/label_image_io.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/io/voxel_grid_io.hpp"

using namespace volmesh;
using Clock = std::chrono::steady_clock;

namespace {

// Runs `batch` (which answers n queries) until 0.5 s have passed; queries per second.
double rate(std::size_t n, const std::function<void()>& batch) {
  const Clock::time_point start = Clock::now();
  std::size_t done = 0;
  double elapsed = 0.0;
  do {
    batch();
    done += n;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < 0.5);
  return done / elapsed;
}

std::unique_ptr<Domain> surface_domain(const std::string& path) {
  TriSurface s = read_surface(path);
  check_surface(s, path, {.find_self_intersections = false});
  return std::make_unique<SurfaceDomain>(std::vector<LabelledSurface>{{std::move(s), 0, path}});
}

std::string human(double per_second) {
  char text[32];
  if (per_second >= 1e6)
    std::snprintf(text, sizeof text, "%.2f M", per_second / 1e6);
  else
    std::snprintf(text, sizeof text, "%.0f k", per_second / 1e3);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: bench_domain_queries CGAL_DATA SDF_GRID.rawiv\n";
    return 2;
  }
  const std::string data = argv[1];
  struct Named {
    std::string name;
    std::function<std::unique_ptr<Domain>()> make;
  };
  const std::vector<Named> domains{
      {"analytic builtin:primitives", [] { return make_builtin_domain("primitives"); }},
      {"layered builtin:layers6 (10 horizons of 32,768 triangles, 1 fault)",
       [] { return make_builtin_domain("layers6"); }},
      {"surface elephant.off (5,558 triangles)",
       [&] { return surface_domain(data + "/meshes/elephant.off"); }},
      {"surface armadillo.off (52,000 triangles)",
       [&] { return surface_domain(data + "/meshes/armadillo.off"); }},
      {"image liver.inr.gz (438x353x165)",
       [&] {
         return std::make_unique<ImageDomain>(read_label_image(data + "/images/liver.inr.gz"));
       }},
      {"SDF grid armadillo 129^3 (.rawiv)",
       [&] { return std::make_unique<SdfGridDomain>(read_rawiv(argv[2])); }},
  };

  std::cout << "| domain | build s | region/s 1 core | region/s 2 cores | crossings/s 1 core | "
               "crossings/s 2 cores | crossings per segment |\n"
               "|---|---:|---:|---:|---:|---:|---:|\n";
  for (const Named& named : domains) {
    const Clock::time_point start = Clock::now();
    const std::unique_ptr<Domain> d = named.make();
    const double build = std::chrono::duration<double>(Clock::now() - start).count();
    const Box3 box = d->bounds();
    const Vec3 lo = box.lo - 0.05 * box.size(), size = 1.1 * box.size();
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> g;
    const std::size_t n = 20000;
    std::vector<Vec3> points(n), a(n), b(n);
    for (std::size_t i = 0; i < n; ++i) {
      points[i] = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(size);
      a[i] = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(size);
      b[i] = a[i] + Vec3(g(rng), g(rng), g(rng)).normalized() * (box.size().norm() / 64);
    }
    std::vector<Index> regions(n);
    std::vector<std::vector<Crossing>> crossings;
    std::size_t found = 0;
    const double region_1 = rate(n, [&] {
      for (std::size_t i = 0; i < n; ++i) regions[i] = d->region(points[i]);
    });
    const double region_2 = rate(n, [&] { d->region(points, regions); });
    const double crossing_1 = rate(n, [&] {
      found = 0;
      for (std::size_t i = 0; i < n; ++i) found += d->crossings(a[i], b[i]).size();
    });
    const double crossing_2 = rate(n, [&] { d->crossings(a, b, crossings); });
    std::printf("| %s | %.3f | %s | %s | %s | %s | %.3f |\n", named.name.c_str(), build,
                human(region_1).c_str(), human(region_2).c_str(), human(crossing_1).c_str(),
                human(crossing_2).c_str(), static_cast<double>(found) / n);
    std::fflush(stdout);
  }
  return 0;
}
