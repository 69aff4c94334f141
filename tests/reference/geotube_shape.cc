// Print the analytic geotube cross-section (include/fsgmpm/reference/
// geotube_reference.h) as CSV: geotube_shape <circumference m> <area m^2>
// [<unit weight N/m^3> = 12000]. The first line holds the scalars as a
// comment; then x,y of the closed shape (x centred at 0, base at y = 0).

#include <fsgmpm/reference/geotube_reference.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

int
main(int argc, char **argv)
{
  if (argc < 3)
    {
      std::fprintf(stderr,
                   "usage: geotube_shape <circumference> <area> "
                   "[<unit weight> = 12000]\n");
      return 1;
    }
  try
    {
      const auto s
        = geotube_reference::solve(std::atof(argv[1]),
                                   std::atof(argv[2]),
                                   argc > 3 ? std::atof(argv[3]) : 12000.);
      std::printf("# height %.6f width %.6f contact_width %.6f tension %.3f "
                  "top_pressure %.3f bottom_pressure %.3f\nx,y\n",
                  s.height,
                  s.width,
                  s.contact_width,
                  s.tension,
                  s.top_pressure,
                  s.bottom_pressure);
      for (const auto &p : s.shape)
        std::printf("%.9f,%.9f\n", p[0], p[1]);
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "geotube_shape: %s\n", e.what());
      return 1;
    }
  return 0;
}
