// Time and memory to build 10^3, 10^4, 10^5 lobules with 30 Lloyd
// iterations (issue: procedural microstructure). One adipose layer of
// 2 mm lobules whose lateral size grows with the count; prints one CSV row
// per size: lobules, seconds for the seeds + Lloyd iterations, seconds per
// iteration, seconds for the final tessellation with faces, peak memory.
//
//   build/benchmarks/lobule_scaling [max_lobules]
//     > benchmarks/lobule_scaling/results/lobule_scaling.csv

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iostream>
#include <random>

#include <ssc/microstructure/clipped_voronoi.h>

int
main(int argc, char **argv)
{
  using namespace dealii;
  const unsigned int max_lobules = argc > 1 ? std::stoi(argv[1]) : 100000;
  const unsigned int iterations  = 30;
  const double       d = 2, thickness = 10; // mm
  std::cout << "lobules,lloyd_iterations,seconds_lloyd,seconds_per_iteration,"
               "seconds_final_with_faces,mean_faces,peak_memory_MB\n";
  for (unsigned int n = 1000; n <= max_lobules; n *= 10)
    {
      const double side = std::sqrt(n * M_PI * d * d * d / 6. / thickness);
      const BoundingBox<3> box(
        std::make_pair(Point<3>(0, 0, 0), Point<3>(side, side, thickness)));
      std::mt19937                           generator(1);
      std::uniform_real_distribution<double> uniform(0., 1.);
      std::vector<Point<3>>                  seeds(n);
      for (auto &p : seeds)
        p = Point<3>(side * uniform(generator),
                     side * uniform(generator),
                     thickness * uniform(generator));
      Timer timer;
      ssc::lloyd_relaxation(box, seeds, iterations);
      const double lloyd = timer.wall_time();
      timer.restart();
      ssc::VoronoiDiagnostics diagnostics;
      const auto              cells =
        ssc::compute_clipped_voronoi(box, seeds, true, diagnostics);
      const double final_time = timer.wall_time();
      double       faces      = 0;
      for (const auto &cell : cells)
        faces += cell.faces.size();
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      std::cout << n << ',' << iterations << ',' << lloyd << ','
                << lloyd / (iterations + 1) << ',' << final_time << ','
                << faces / n << ',' << memory.VmHWM / 1024. << std::endl;
    }
}
