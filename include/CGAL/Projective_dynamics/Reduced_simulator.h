// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_REDUCED_SIMULATOR_H
#define CGAL_PROJECTIVE_DYNAMICS_REDUCED_SIMULATOR_H

/// \file Reduced_simulator.h
/// Reduced and hyper-reduced Projective Dynamics (SPEC 12).  Positions live in the position
/// subspace, `q = U a` (`Position_subspace.h`; `a` is k x 3), and each step minimises the full
/// objective `g(U a)` over `a`:
/// - local step: projections `p` of the elements;
/// - global step: `K a = U^T M s / h^2 + U^T S^T W p` with the k x k dense
///   `K = U^T M U / h^2 + sum_i U^T S_i^T w_i S_i U`, summed over all elements once per group and
///   factored once (a stiffness or time-step change refactors only `K`).
///
/// Reduced PD projects every element (needs `U a` at every vertex each iteration); hyper-reduced
/// PD (the default) projects only `s` sampled elements per group, evaluated at their vertices
/// only (`U_used a`), fits `b = argmin |J V b - p_S|^2` in the group's projection subspace `V`
/// (`Projection_subspace.h`; the l x l normal matrix factored once) and adds `F b`,
/// `F = U^T S^T W V` precomputed (k x l).  Its per-iteration cost does not depend on the mesh size.
///
/// Pinned and grabbed vertices are held by soft springs in the reduced space (the subspace
/// cannot hold a single vertex exactly): `kappa/2 |U_i a - target_i|^2` with
/// `kappa = pin_stiffness * (mean vertex mass) / h^2` added to `g`.  A floor holds at the collision
/// vertices (by default the position samples and, hyper-reduced, the sampled elements'
/// vertices; `set_collision_vertices` chooses others, e.g. the whole drawn surface): after the
/// iterations, `a` changes by the smallest amount in the norm of `U^T M U`, along the floor's
/// normal, that puts every collision vertex on or above the floor (a quadratic program solved
/// to a relative 1e-10 of the body's extent), holding the pinned and grabbed vertices' heights.
/// With the samples' subspace the change is sought among the samples' translations (a smooth
/// lift of the body, m unknowns whatever the number of vertices in contact); with a basis handed
/// in, among all its columns near the contact.  Other vertices may dip below; no friction; no
/// self-collision.
/// Full positions are made only on request (`positions()`, `positions_of`).
///
/// The precomputation (subspaces, sampled elements, projected matrices) can take minutes on a
/// large mesh: it reports its progress (`Reduction_options::progress`, the named parameter
/// `progress_callback`, which may cancel it), and `save` writes it to a file that `load` reads
/// back for the same model and reduction options, refusing another's with the reason:
/// \code
/// PD::Reduced_simulator sim(model, PD::parameters::number_of_samples(150).progress_callback(report));
/// sim.save("bar.pdr");
/// // later, or in another run: no precomputation
/// PD::Reduced_simulator again = PD::Reduced_simulator::load(model, "bar.pdr", PD::parameters::number_of_samples(150));
/// \endcode

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// Reported during the precomputation of `Reduced_simulator`.
struct Reduced_precomputation_progress
{
  /// "position subspace", "projected matrices", "sampled elements", "projection subspaces"
  /// (hyper-reduced only), "done"
  std::string stage;
  double fraction = 0; ///< overall estimate in [0, 1], never decreasing; 1 with "done"
};

/// The subspace sizes (named parameters of `Reduced_simulator`).  Defaults: the reference's.
/// All but `pin_stiffness` and `progress` shape the subspaces: a saved precomputation is loaded
/// only with the same values (see `Reduced_simulator::load`).
struct Reduction_options
{
  int samples = 150;                        ///< position samples `m`; `k = 4 m` columns
  double radius_multiplier = 1.1;           ///< of the position samples' covering radius
  bool hyper_reduction = true;              ///< fit sampled projections (true) or project all elements
  int constraint_samples = 60;              ///< samples of the projection subspace, per group
  double constraint_radius_multiplier = 2.2;
  int projection_columns = 120;             ///< `l` per group
  int sampled_elements = 1000;              ///< `s` per group, at least `l + 20` (capped to the group's size)
  double pin_stiffness = 1e3;               ///< soft pins and grabs, relative to mean mass / h^2
  /// Called between the stages of the precomputation (and within them, per element group);
  /// return false to cancel: the constructor then throws `Cancelled`.
  std::function<bool(const Reduced_precomputation_progress&)> progress;
};

/// Wall-clock seconds of the last step (sums over the iterations) and of the precomputation.
struct Reduced_step_timings
{
  double local = 0;  ///< positions of the used vertices, projections and (hyper-reduced) fits
  double global = 0; ///< right-hand side and the k x k solves
  double contact = 0; ///< the floor's push (all floors, all rounds)
  double total = 0;
  int contact_vertices = 0;       ///< collision vertices in the last push's problem (0: nothing touched a floor)
  int contact_columns = 0;        ///< basis columns those vertices touch: the size of that problem
  int contact_factorizations = 0; ///< dense factorizations of that size the push needed
  double factorization = 0;  ///< the last factorisation of K
  double precomputation = 0; ///< subspaces, projected matrices, fits (constructor), or reading them (`load`)
};

class Reduced_simulator
{
public:
  /// Builds the subspaces of `model` and starts at rest.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{time_step, number_of_iterations, gravity, number_of_threads, friction} as for `Simulator` \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_samples} position samples `m`, `k = 4m`; `int`; default 150 \cgalParamNEnd
  ///   \cgalParamNBegin{radius_multiplier} `> 1`; `double`; default 1.1 \cgalParamNEnd
  ///   \cgalParamNBegin{hyper_reduction} `bool`; default true \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_constraint_samples} `int`; default 60 \cgalParamNEnd
  ///   \cgalParamNBegin{constraint_radius_multiplier} `> 1`; `double`; default 2.2 \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_projection_columns} `l` per group; `int`; default 120 \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_sampled_elements} `s >= l + 20` per group; `int`; default 1000 \cgalParamNEnd
  ///   \cgalParamNBegin{pin_stiffness} `> 0`; `double`; default 1000 \cgalParamNEnd
  ///   \cgalParamNBegin{progress_callback} `bool(const Reduced_precomputation_progress&)` (false
  ///     cancels) or `void(const Reduced_precomputation_progress&)`; default none \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws Invalid_input for an option out of range (samples above the vertex count, `s < l + 20`,
  ///         ...), with the reason; Numerical_failure if `U^T M U` is singular (a vertex of zero mass
  ///         in a sample's support only, or supports too small to span affine maps); Cancelled
  ///         when the progress callback returns false.
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Reduced_simulator(Elastic_model model, const NamedParameters& np = parameters::default_values())
    : Reduced_simulator(std::move(model), Simulator::options_of(np), reduction_options_of(np))
  {}
  Reduced_simulator(Elastic_model model, const Simulator_options& options, const Reduction_options& reduction);
  /// With an explicit basis `U` (n x k, e.g. the identity) instead of the samples'; `U` must
  /// reproduce the rest positions (`U a = x` solvable exactly), which the start state uses.
  /// Its collision vertices are all vertices until `set_collision_vertices` says otherwise.
  /// \throws Invalid_input for a wrong row count or a basis that does not reproduce the rest shape.
  Reduced_simulator(Elastic_model model, const Eigen::SparseMatrix<double, Eigen::RowMajor>& basis,
                    const Simulator_options& options, const Reduction_options& reduction);
  ~Reduced_simulator();
  Reduced_simulator(Reduced_simulator&&) noexcept;
  Reduced_simulator& operator=(Reduced_simulator&&) noexcept;

  template <class NamedParameters>
  static Reduction_options reduction_options_of(const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    Reduction_options r;
    r.samples = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_samples), r.samples);
    r.radius_multiplier = choose_parameter(get_parameter(np, internal_np::radius_multiplier), r.radius_multiplier);
    r.hyper_reduction = choose_parameter(get_parameter(np, internal_np::hyper_reduction), r.hyper_reduction);
    r.constraint_samples = choose_parameter(get_parameter(np, internal_np::number_of_constraint_samples), r.constraint_samples);
    r.constraint_radius_multiplier =
        choose_parameter(get_parameter(np, internal_np::constraint_radius_multiplier), r.constraint_radius_multiplier);
    r.projection_columns = choose_parameter(get_parameter(np, internal_np::number_of_projection_columns), r.projection_columns);
    r.sampled_elements = choose_parameter(get_parameter(np, internal_np::number_of_sampled_elements), r.sampled_elements);
    r.pin_stiffness = choose_parameter(get_parameter(np, internal_np::pin_stiffness), r.pin_stiffness);
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::progress_callback_t>::value)
    {
      const auto f = get_parameter(np, internal_np::progress_callback);
      typedef std::decay_t<decltype(f)> F;
      if constexpr(std::is_void_v<std::invoke_result_t<const F&, const Reduced_precomputation_progress&>>)
        r.progress = [f](const Reduced_precomputation_progress& p) { return f(p), true; };
      else
        r.progress = f;
    }
    return r;
  }

  /// Writes the precomputation -- the basis `U` and its samples, the projected matrices, and
  /// (hyper-reduced) each group's sampled elements, projection subspace rows and `F` -- to a
  /// binary file (`.pdr`), with the identity of the model (its vertex count and element
  /// connectivity, the edge lengths and rest positions, each element group's type, size and
  /// constraint constants) and the reduction options that shaped it.  Not saved: the state,
  /// pins, grabs, floors, collision vertices chosen by `set_collision_vertices`, the
  /// stiffnesses and masses, and the `Simulator_options` (all given again on loading).
  /// \throws Invalid_input if the file cannot be written.
  void save(const std::string& path) const;

  /// A simulator of `model` with the precomputation read from `path` (written by `save`)
  /// instead of computed, at rest, as the constructor leaves it: the same trajectories, bit for
  /// bit.  The time step, iterations, gravity, threads, pin stiffness and the model's
  /// stiffnesses and masses may differ from those of the saved one (they change only `K` and
  /// `U^T M U`, which are computed on loading).  Named parameters as for the constructor
  /// (`progress_callback` is not called); the reduction options that shape the subspaces (all
  /// but `pin_stiffness`; the hyper-reduction's only when it is on) must equal the saved ones.
  /// Hyper-reduced, loading took 1/17 to 1/63 of the precomputation on the cantilevers of
  /// bench_reduced_pd (24k and 41k tetrahedra; the manual has the table).
  /// \throws Invalid_input "cannot load the reduced simulator from '<path>': <reason>", the reason
  ///         one of: not a reduced simulator file; file format version; "it belongs to a mesh with
  ///         other connectivity" (vertex count or elements); "... with other edge lengths";
  ///         "its rest positions are elsewhere (moved or turned)"; "made for N element groups";
  ///         "element group g is ... in the file"; "made with other reduction options: <name> ...";
  ///         the file is truncated or corrupt; or an option out of range, as the constructor.
  template <class NamedParameters = parameters::Default_named_parameters>
  static Reduced_simulator load(Elastic_model model, const std::string& path,
                                const NamedParameters& np = parameters::default_values())
  {
    return load(std::move(model), path, Simulator::options_of(np), reduction_options_of(np));
  }
  static Reduced_simulator load(Elastic_model model, const std::string& path, const Simulator_options& options,
                                const Reduction_options& reduction);

  /// One time step; `after_iteration(k, a)` sees the coordinates after the global step of
  /// iteration `k` (before the floor corrects them).
  /// \throws Numerical_failure if the coordinates stop being finite (the state is kept).
  void step(const std::function<void(int, const Eigen::MatrixXd&)>& after_iteration = {});

  /// The coordinates `a` (k x 3) and their velocities.
  const Eigen::MatrixXd& coordinates() const;
  const Eigen::MatrixXd& coordinate_velocities() const;
  /// \throws Invalid_input for a wrong size or a non-finite entry.
  void set_coordinates(const Eigen::MatrixXd& a);
  void set_coordinate_velocities(const Eigen::MatrixXd& a_dot);
  /// Full positions `U a` (n x 3; costs a sparse product) and those of some vertices only.
  Positions positions() const;
  Positions positions_of(const std::vector<int>& vertices) const;
  Positions velocities() const;
  /// Sets `a` (or its velocity) to the M-least-squares fit of `q`: `(U^T M U)^{-1} U^T M q`.
  void set_positions(const Positions& q);
  void set_velocities(const Positions& v);
  void set_external_forces(const Positions& f);

  /// Soft pins at the current positions (replacing earlier ones; refactors K).
  void set_pinned_vertices(const std::vector<int>& vertices);
  void grab(const std::vector<int>& vertices, const Positions& targets);
  void move_grabbed(const Positions& targets);
  void release_grabbed();
  void add_floor(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);
  void clear_obstacles();
  void set_collision_vertices(const std::vector<int>& vertices);

  /// Refactor only K (k x k) on the next step.
  void set_time_step(double h);
  void set_stiffness(int group, double stiffness);
  void set_iterations(int iterations);

  const Eigen::SparseMatrix<double, Eigen::RowMajor>& basis() const;
  int dimension() const;                       ///< k
  const std::vector<int>& samples() const;     ///< position samples (empty for an explicit basis)
  std::vector<int> sampled_elements() const;   ///< all groups', hyper-reduced
  std::vector<int> used_vertices() const;      ///< the vertices the hyper-reduced local step reads
  const Simulator_options& options() const;
  const Reduction_options& reduction_options() const;
  const Elastic_model& model() const;
  const Reduced_step_timings& last_step_timings() const;
  int number_of_factorizations() const;

private:
  Reduced_simulator() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace Projective_dynamics
} // namespace CGAL

#endif
