#include <fsgmpm/particles/polygon_inside.h>

#include <algorithm>

namespace fsgmpm
{
  PolygonInside::PolygonInside(const std::vector<Point<2>> &v)
    : vertices(v)
  {
    const unsigned int n = vertices.size();
    if (n == 0)
      return;
    y_low = y_high = vertices[0][1];
    for (const Point<2> &x : vertices)
      {
        y_low  = std::min(y_low, x[1]);
        y_high = std::max(y_high, x[1]);
      }
    const unsigned int n_bands = std::max(n, 1u);
    band_height                = (y_high - y_low) / n_bands;
    if (!(band_height > 0))
      band_height = 1;
    band_start.assign(n_bands + 1, 0);
    // Count, then fill (the edges of a band in ascending order). A
    // horizontal edge never changes the answer and is left out.
    for (const bool fill : {false, true})
      {
        std::vector<unsigned int> next;
        if (fill)
          {
            for (unsigned int k = 0; k < n_bands; ++k)
              band_start[k + 1] += band_start[k];
            band_edges.resize(band_start.back());
            next.assign(band_start.begin(), band_start.end() - 1);
          }
        for (unsigned int i = 0, j = n - 1; i < n; j = i++)
          {
            const double ya = vertices[i][1], yb = vertices[j][1];
            if (ya == yb)
              continue;
            for (unsigned int k = band(std::min(ya, yb));
                 k <= band(std::max(ya, yb));
                 ++k)
              if (fill)
                band_edges[next[k]++] = i;
              else
                ++band_start[k + 1];
          }
      }
  }



  unsigned int
  PolygonInside::band(const double y) const
  {
    const double       t       = (y - y_low) / band_height;
    const unsigned int n_bands = band_start.size() - 1;
    if (!(t > 0))
      return 0;
    return t >= n_bands ? n_bands - 1 : static_cast<unsigned int>(t);
  }



  bool
  PolygonInside::operator()(const Point<2> &x) const
  {
    // An edge changes the answer only if min(y_a, y_b) <= x_y < max(y_a,
    // y_b): none does outside [y_low, y_high) (nor for a y that is NaN).
    if (!(x[1] >= y_low && x[1] < y_high))
      return false;
    const unsigned int n  = vertices.size();
    const unsigned int k  = band(x[1]);
    bool               in = false;
    for (unsigned int e = band_start[k]; e < band_start[k + 1]; ++e)
      {
        const unsigned int i = band_edges[e], j = i == 0 ? n - 1 : i - 1;
        if (edge_crosses_ray(vertices[i], vertices[j], x))
          in = !in;
      }
    return in;
  }
} // namespace fsgmpm
