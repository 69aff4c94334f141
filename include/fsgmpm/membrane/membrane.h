#ifndef fsgmpm_membrane_membrane_h
#define fsgmpm_membrane_membrane_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <fsgmpm/membrane/membrane_fe.h>
#include <fsgmpm/membrane/membrane_ground.h>

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /// Material of a membrane (per metre in 2D: EA and tension in N/m).
  struct MembraneProperties
  {
    double axial_stiffness = 5e7; ///< EA = E * thickness (N/m)
    double poisson_ratio   = 0.3; ///< in-plane nu (3D triangles only)
    double areal_mass      = 0.5; ///< rho_A (kg/m^2)
    /// Pre-strain: the rest size is the initial size / (1 + eps0) (2D
    /// length, 3D each edge), so eps0 > 0 starts the membrane in tension.
    double initial_strain = 0;
    /// Polynomial degree of the membrane elements (FE_SimplexP, 1 or 2).
    unsigned int element_degree = 1;
  };

  /**
   * A geomembrane as a finite-element structure inside the MPM frame (FEM-MPM
   * coupling, paper Section 2.1.2): tension-only cables in 2D, membrane
   * triangles in 3D, on deal.II's FE machinery (MembraneFE: FE_SimplexP of
   * degree 1 or 2 on the codim-1 triangulation, forces by quadrature). Its
   * nodes are the elements' support points; they carry lumped mass and
   * velocity and exchange mass, momentum and their element forces with the
   * background grid like material points (MembraneCoupling, in step/), every
   * support point alike. The element forces come from the current node
   * positions against the rest geometry (total Lagrangian and stateless: slack
   * is never forgotten and the strain cannot drift).
   *
   * The geometry enters as a deal.II codimension-one triangulation
   * (Triangulation<dim-1, dim>); its initial shape, shrunk by 1 + initial
   * strain, is the rest state. For the geometric work (loops, slip,
   * splitting, time-step bounds, output) the membrane is also a set of
   * straight "elements" between the nodes: the cells themselves at degree 1,
   * their halves (2D) or quarter triangles (3D) at degree 2.
   *
   * Its contact models are their own pieces: the frictionless slip along
   * the fill (MembraneSlip, switched by tangential_slip) and the rigid
   * ground (MembraneGround, held in ground).
   */
  template <int dim>
  class Membrane
  {
  public:
    static constexpr unsigned int nodes_per_element = dim;

    /// @p edge_middle_points: at degree 2, the initial positions of the
    /// edge support points of a curved mesh (a second-order Gmsh surface),
    /// keyed by the edge's two vertex indices in @p mesh (smaller first);
    /// edges not listed take their straight midpoint (in 2D, the arc
    /// through the neighbours). Ignored at degree 1.
    Membrane(const Triangulation<dim - 1, dim> &mesh,
             const MembraneProperties          &properties,
             const std::map<std::pair<unsigned int, unsigned int>, Point<dim>>
               &edge_middle_points
             = {});

    /// (Re)builds the finite elements from the rest structure (rest_vertex,
    /// fe_cells, vertex_node, edge_node): after a split, or after the
    /// structure was restored from a checkpoint.
    void
    setup_finite_elements();

    /// The membrane's finite elements.
    const MembraneFE<dim> &
    get_fe() const
    {
      return *fe;
    }

    /// The node of support point (DoF) @p i of get_fe().
    unsigned int
    support_point_node(const unsigned int i) const
    {
      return node_of_dof[i];
    }

    /// The active cell of get_fe() that cell @p c of fe_cells is.
    unsigned int
    active_cell_of(const unsigned int c) const
    {
      return active_cell_of_cell[c];
    }

    unsigned int
    n_nodes() const
    {
      return position.size();
    }
    unsigned int
    n_elements() const
    {
      return elements.size();
    }

    /// Element forces on the nodes (force) and element tensions from the
    /// current positions: cable T = EA max(0, lambda - 1) in 2D; the
    /// Saint Venant-Kirchhoff membrane with the compression cut-off of
    /// Eqs. (9)-(10) in 3D (MembraneFE). The tension of an element is its
    /// cell's, averaged over the quadrature points.
    void
    compute_forces();

    /// 2D: split every cell with an element longer than @p max_length into
    /// two (the rest cell halved, so that strain and total mass are
    /// unchanged), so the fluid cannot leak between nodes. The new support
    /// points take the cell's interpolated position and velocity (the
    /// midpoint at degree 1, the quadratic at degree 2); the lumped masses
    /// are recomputed. Returns the number of new nodes; their cell is that
    /// of the element's first node (near them: the location walks from
    /// there, MembraneCoupling::relocate()). 3D: returns the number of
    /// elements with an edge longer than max_length (not split).
    unsigned int
    split_long_elements(const double max_length);

    /// Length and signed x-y area (positive counter-clockwise) of a closed
    /// loop of nodes.
    double
    loop_length(const std::vector<unsigned int> &loop) const;
    double
    loop_area(const std::vector<unsigned int> &loop) const;

    /// Longest element edge in the current configuration.
    double
    max_element_length() const;

    /// Current length (2D) or area (3D) of element e.
    double
    element_size(const unsigned int e) const;

    /**
     * One element's elastic and geometric stiffness in the form the nodal
     * time-step bound takes (MembraneCoupling::time_step()): with
     * F = sum_a u_a (x) g_a over its nodes a (displacements u_a, shape
     * gradients g_a along the element), its energy is at most
     * size/2 (sum_a |g_a| |C^1/2 u_a|)^2, C = modulus. By Cauchy-Schwarz its
     * stiffness matrix is then at most diag_a(w_a size sum_b (|g_b|^2 / w_b)
     * C) for any positive weights w; and since moving the nodes with the
     * grid, u_a = sum_i N_i(x_a) u_i, only replaces the g_a by
     * G_i = sum_a N_i(x_a) g_a, the same holds for the stiffness the grid
     * nodes i see, with G_i in place of g_a.
     */
    struct ElementStiffness
    {
      std::array<unsigned int, dim>   nodes;
      std::array<Tensor<1, dim>, dim> gradient;
      /// Length (cable) or area (triangle), times 4/3 at degree 2.
      double size = 0;
      /// Cables: EA t(x)t along the cable (none with slip, which the loop
      /// stiffness bounds; 3D slip keeps its part along z) plus the
      /// tension's T (I - t(x)t) across it. Triangles: the plane-stress
      /// modulus's largest eigenvalue EA / (1 - |nu|) in the plane plus the
      /// major tension in every direction.
      SymmetricTensor<2, dim> modulus;
    };

    /// ElementStiffness of every element (2D, 3D without slip), or of every
    /// triangle edge as a cable (3D with slip, an edge of two triangles
    /// twice: a safe bound).
    std::vector<ElementStiffness>
    element_stiffness() const;

    /// Per node, the stiffness acting on that node alone: the ground penalty
    /// along y (MembraneGround::add_stiffness()) and, with slip, the loop's
    /// axial stiffness MembraneSlip::loop_axial_stiffness() in every
    /// direction.
    std::vector<SymmetricTensor<2, dim>>
    node_stiffness() const;

    /// Total current length (2D) or area (3D).
    double
    total_size() const;

    /// 2D closed membrane: the signed area enclosed by the node polygon
    /// (positive when counter-clockwise).
    double
    enclosed_area() const;

    /// Closed polygon of the nodes in element order (2D) or the first ring
    /// (3D extruded membrane), for output.
    std::vector<Point<dim>>
    ordered_nodes() const;

    double
    kinetic_energy() const;
    /// The elements' elastic energy plus the ground penalty's.
    double
    strain_energy() const;

    /// True if the elements form one closed loop (2D).
    bool
    is_closed_loop() const;

    /// The nodes in loop order: the first ring of an extruded 3D membrane,
    /// else the first node of every element (a 2D closed loop is stored in
    /// loop order).
    std::vector<unsigned int>
    loop_nodes() const;

    MembraneProperties properties;

  private:
    /// Sets rings if every z level of the nodes is one closed loop of
    /// element edges (3D).
    void
    find_rings();

  public:
    /// Frictionless contact with the fill (2D, 3D rings; MembraneSlip):
    /// the coupling equalizes the stretch after every position update, and
    /// node_stiffness() bounds the axial part by the loop's.
    bool tangential_slip = false;
    /// Rigid frictionless ground acting on the nodes (off by default).
    MembraneGround<dim> ground;

    // --- nodes -----------------------------------------------------------
    std::vector<Point<dim>>     position;
    std::vector<Tensor<1, dim>> velocity;
    std::vector<double>         mass;
    /// Element forces acting on the node (tension pulls nodes together).
    std::vector<Tensor<1, dim>> force;
    /// Background cell holding the node, by its number in the whole grid
    /// (MPI: the same on every process, whatever window of the grid it
    /// holds).
    std::vector<unsigned int> cell;

    /// 3D membrane extruded along z (ellipse or polygon shapes): its nodes
    /// at each z level in loop order (counter-clockwise in x-y), and the
    /// rest lengths of the ring edges k -> k+1. Empty for other membranes.
    std::vector<std::vector<unsigned int>> rings;
    std::vector<std::vector<double>>       ring_rest_length;

    // --- elements (straight pieces between nodes, see above) -------------
    std::vector<std::array<unsigned int, dim>> elements;
    /// Rest length (2D) or rest area (3D).
    std::vector<double> rest_size;
    /// Cable tension (2D) or major principal membrane stress (3D), N/m.
    std::vector<double> tension;
    /// 3D: minor principal membrane stress after the cut-off (N/m).
    std::vector<double> minor_tension;

    // --- rest structure of the finite elements ----------------------------
    /// Rest positions of the mesh vertices.
    std::vector<Point<dim>> rest_vertex;
    /// The cells by their rest vertices.
    std::vector<std::array<unsigned int, dim>> fe_cells;
    /// The node at each rest vertex.
    std::vector<unsigned int> vertex_node;
    /// Degree 2: the node at the midpoint of each cell edge, as
    /// {vertex, vertex, node} with the smaller vertex first.
    std::vector<std::array<unsigned int, 3>> edge_node;
    /// Degree 2: the rest position of each edge's middle node (on the rest
    /// curve: rest cells are curved where the initial membrane is).
    std::vector<Point<dim>> edge_rest_point;
    /// The cell (index into fe_cells) each element lies in.
    std::vector<unsigned int> element_cell;

  private:
    std::unique_ptr<MembraneFE<dim>> fe;
    /// The node of each support point (DoF) of fe.
    std::vector<unsigned int> node_of_dof;
    /// The active cell of fe holding each of fe_cells.
    std::vector<unsigned int> active_cell_of_cell;
    /// Scratch of compute_forces().
    std::vector<Point<dim>>            dof_position;
    std::vector<Tensor<1, dim>>        dof_force;
    std::vector<std::array<double, 2>> cell_stress;

    /// The elements of cell c (degree 1: the cell; degree 2: its halves or
    /// quarters), appended to elements with their rest sizes.
    void
    add_elements_of_cell(const unsigned int c);

    /// The index in edge_node of edge (v, w); invalid if none. Looked up
    /// in edge_lookup (rebuilt when invalidated: edge_node is public, and
    /// a checkpoint or a split rewrites it), so that building a large
    /// degree-2 membrane is not quadratic in its edges.
    unsigned int
    edge_index(const unsigned int v, const unsigned int w) const;
    mutable std::map<std::pair<unsigned int, unsigned int>, unsigned int>
                 edge_lookup;
    mutable bool edge_lookup_valid = true;

    /// The node at the midpoint of edge (v, w); invalid if none.
    unsigned int
    node_of_edge(const unsigned int v, const unsigned int w) const;
  };
} // namespace fsgmpm

#endif
