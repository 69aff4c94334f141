#include <deal.II/base/exceptions.h>

#include <fsgmpm/membrane/gmsh_surface.h>

#include <array>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace fsgmpm
{
  namespace
  {
    /// A triangle by its Gmsh node tags: 3 corners, then at second order
    /// the nodes of edges 0-1, 1-2, 2-0 (Gmsh's numbering of type 9).
    struct GmshTriangle
    {
      std::vector<std::size_t> nodes;
    };

    /// Nodes per element of the Gmsh types a membrane file may hold:
    /// triangles (2, 9) and the lower-dimensional entities Gmsh writes for
    /// physical groups (lines 1, 8; points 15), which are skipped.
    int
    nodes_of_type(const int type)
    {
      switch (type)
        {
          case 1:
            return 2;
          case 2:
            return 3;
          case 8:
            return 3;
          case 9:
            return 6;
          case 15:
            return 1;
          default:
            return -1;
        }
    }

    class Parser
    {
    public:
      Parser(const std::string &file_name, const std::string &parameter)
        : in(file_name)
        , file_name(file_name)
        , parameter(parameter)
      {
        AssertThrow(in.good(),
                    ExcMessage(parameter + ": cannot open the Gmsh file <"
                               + file_name + ">."));
      }

      void
      fail(const std::string &what) const
      {
        AssertThrow(false,
                    ExcMessage(parameter + " <" + file_name + ">: " + what));
      }

      template <typename T>
      T
      read(const char *what)
      {
        T value;
        if (!(in >> value))
          fail(std::string("the file ends or is malformed where ") + what
               + " was expected.");
        return value;
      }

      /// Skips to the line "$Name" and returns true, or false at the end.
      bool
      next_section(std::string &name)
      {
        std::string word;
        while (in >> word)
          if (!word.empty() && word[0] == '$' && word.rfind("$End", 0) != 0)
            {
              name = word.substr(1);
              return true;
            }
        return false;
      }

      void
      add_element(const int type, const std::vector<std::size_t> &nodes)
      {
        if (type == 2 || type == 9)
          triangles.push_back({nodes});
      }

      void
      check_type(const int type)
      {
        if (nodes_of_type(type) < 0)
          fail("holds Gmsh elements of type " + std::to_string(type)
               + "; a membrane surface consists of 3-node or 6-node "
                 "triangles (Gmsh types 2 and 9; set Mesh.ElementOrder = 1 "
                 "or 2 and mesh the surface with triangles).");
      }

      void
      parse()
      {
        std::string section;
        double      version = 0;
        while (next_section(section))
          if (section == "MeshFormat")
            {
              version         = read<double>("the format version");
              const int ascii = read<int>("the file type");
              read<int>("the data size");
              if (ascii != 0)
                fail("is a binary Gmsh file; save it as ASCII (Gmsh option "
                     "Mesh.Binary = 0).");
              // 4.0 lays out $Nodes and $Elements differently from 4.1.
              if (!(version >= 2 && version < 3)
                  && !(version > 4.05 && version < 5))
                fail("has Gmsh format " + std::to_string(version)
                     + "; formats 2.2 and 4.1 are read.");
            }
          else if (section == "Nodes")
            {
              if (version == 0)
                fail("has no $MeshFormat section before $Nodes.");
              if (version < 3)
                {
                  const auto n = read<std::size_t>("the number of nodes");
                  for (std::size_t i = 0; i < n; ++i)
                    {
                      const auto tag = read<std::size_t>("a node tag");
                      Point<3>   x;
                      for (unsigned int d = 0; d < 3; ++d)
                        x[d] = read<double>("a node coordinate");
                      nodes[tag] = x;
                    }
                }
              else
                {
                  const auto n_blocks = read<std::size_t>("the node blocks");
                  read<std::size_t>("the number of nodes");
                  read<std::size_t>("the smallest node tag");
                  read<std::size_t>("the largest node tag");
                  for (std::size_t b = 0; b < n_blocks; ++b)
                    {
                      read<int>("an entity dimension");
                      read<int>("an entity tag");
                      read<int>("the parametric flag");
                      const auto n = read<std::size_t>("a block's node count");
                      std::vector<std::size_t> tags(n);
                      for (auto &tag : tags)
                        tag = read<std::size_t>("a node tag");
                      for (const auto tag : tags)
                        {
                          Point<3> x;
                          for (unsigned int d = 0; d < 3; ++d)
                            x[d] = read<double>("a node coordinate");
                          // Parametric nodes carry their (u, v) on the
                          // line too: skip the rest of the line.
                          std::string rest;
                          std::getline(in, rest);
                          nodes[tag] = x;
                        }
                    }
                }
            }
          else if (section == "Elements")
            {
              if (version == 0)
                fail("has no $MeshFormat section before $Elements.");
              if (version < 3)
                {
                  const auto n = read<std::size_t>("the number of elements");
                  for (std::size_t i = 0; i < n; ++i)
                    {
                      read<std::size_t>("an element tag");
                      const int type   = read<int>("an element type");
                      const int n_tags = read<int>("the number of tags");
                      for (int k = 0; k < n_tags; ++k)
                        read<long>("an element tag");
                      check_type(type);
                      std::vector<std::size_t> element(nodes_of_type(type));
                      for (auto &tag : element)
                        tag = read<std::size_t>("an element's node");
                      add_element(type, element);
                    }
                }
              else
                {
                  const auto n_blocks = read<std::size_t>("the element blocks");
                  read<std::size_t>("the number of elements");
                  read<std::size_t>("the smallest element tag");
                  read<std::size_t>("the largest element tag");
                  for (std::size_t b = 0; b < n_blocks; ++b)
                    {
                      read<int>("an entity dimension");
                      read<int>("an entity tag");
                      const int  type = read<int>("an element type");
                      const auto n    = read<std::size_t>("a block's size");
                      check_type(type);
                      for (std::size_t i = 0; i < n; ++i)
                        {
                          read<std::size_t>("an element tag");
                          std::vector<std::size_t> element(nodes_of_type(type));
                          for (auto &tag : element)
                            tag = read<std::size_t>("an element's node");
                          add_element(type, element);
                        }
                    }
                }
            }
        if (version == 0)
          fail("is not a Gmsh mesh (no $MeshFormat section).");
      }

      std::ifstream                             in;
      const std::string                         file_name, parameter;
      std::unordered_map<std::size_t, Point<3>> nodes;
      std::vector<GmshTriangle>                 triangles;
    };
  } // namespace



  void
  read_gmsh_surface(const std::string   &file_name,
                    const std::string   &parameter,
                    Triangulation<2, 3> &surface,
                    EdgeMiddlePoints    &middle_points)
  {
    Parser parser(file_name, parameter);
    parser.parse();
    if (parser.triangles.empty())
      parser.fail("holds no triangles; the membrane surface must be meshed "
                  "with 3-node or 6-node triangles.");
    const std::size_t order_nodes = parser.triangles.front().nodes.size();

    // The corners become the triangulation's vertices, numbered in order of
    // first use.
    std::unordered_map<std::size_t, unsigned int> vertex_of_tag;
    std::vector<Point<3>>                         vertices;
    std::vector<CellData<2>>                      cells;
    auto point_of = [&](const std::size_t tag) {
      const auto it = parser.nodes.find(tag);
      if (it == parser.nodes.end())
        parser.fail("an element refers to node " + std::to_string(tag)
                    + ", which the $Nodes section does not define.");
      return it->second;
    };
    middle_points.clear();
    for (const auto &triangle : parser.triangles)
      {
        if (triangle.nodes.size() != order_nodes)
          parser.fail("mixes first- and second-order triangles; mesh the "
                      "whole surface with one element order.");
        CellData<2> cell(3);
        for (unsigned int k = 0; k < 3; ++k)
          {
            const std::size_t tag = triangle.nodes[k];
            auto              it  = vertex_of_tag.find(tag);
            if (it == vertex_of_tag.end())
              {
                it = vertex_of_tag.emplace(tag, vertices.size()).first;
                vertices.push_back(point_of(tag));
              }
            cell.vertices[k] = it->second;
          }
        if (order_nodes == 6)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int a      = cell.vertices[k],
                                 b      = cell.vertices[(k + 1) % 3];
              const Point<3> m          = point_of(triangle.nodes[3 + k]);
              const auto [it, inserted] = middle_points.emplace(
                std::make_pair(std::min(a, b), std::max(a, b)), m);
              if (!inserted && it->second.distance(m) > 1e-12 * (1. + m.norm()))
                parser.fail("two triangles share an edge but give it "
                            "different middle nodes; the second-order mesh "
                            "is not conforming.");
            }
        cells.push_back(cell);
      }
    try
      {
        surface.create_triangulation(vertices, cells, SubCellData());
      }
    catch (ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        parser.fail("is not a valid triangle surface: " + info.str());
      }
  }
} // namespace fsgmpm
