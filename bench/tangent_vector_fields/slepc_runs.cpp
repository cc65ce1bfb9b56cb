// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "slepc_runs.h"
#include "peak_memory.h"

#include <slepceps.h>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace tvf_bench {

namespace {

// Every PETSc call is checked; a failure becomes an exception naming the call
// (PETSc's error handler has printed its traceback to stderr already).
void check(PetscErrorCode code, const char* call)
{
  if(code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw std::runtime_error(std::string(call) + " failed (PETSc error " + std::to_string(code) + ": " +
                           (text ? text : "unknown") + ")");
}
#define TVF_PETSC(call) check((call), #call)

void check_mpi(int code, const char* call)
{
  if(code != MPI_SUCCESS) throw std::runtime_error(std::string(call) + " failed (MPI error " + std::to_string(code) + ")");
}
#define TVF_MPI(call) check_mpi((call), #call)

// A PETSc object destroyed with its scope.
template <class T, PetscErrorCode (*destroy)(T*)>
class Petsc_object
{
public:
  Petsc_object() = default;
  Petsc_object(Petsc_object&& other) noexcept : object_(other.object_) { other.object_ = nullptr; }
  Petsc_object(const Petsc_object&) = delete;
  Petsc_object& operator=(const Petsc_object&) = delete;
  ~Petsc_object()
  {
    if(object_) destroy(&object_);
  }
  T* address() { return &object_; }
  operator T() const { return object_; }

private:
  T object_ = nullptr;
};
typedef Petsc_object<Mat, MatDestroy> Petsc_mat;
typedef Petsc_object<Vec, VecDestroy> Petsc_vec;
typedef Petsc_object<EPS, EPSDestroy> Petsc_eps;
typedef Petsc_object<PetscViewer, PetscViewerDestroy> Petsc_viewer;

// A fresh options database for one run: slicing creates its own sub-solvers, which see
// only the database (what is set in code on the outer solver does not reach them).
class Options_scope
{
public:
  explicit Options_scope(const std::string& options)
  {
    TVF_PETSC(PetscOptionsCreate(&database_));
    try
    {
      TVF_PETSC(PetscOptionsInsertString(database_, options.c_str()));
      TVF_PETSC(PetscOptionsPush(database_));
    }
    catch(...)
    {
      PetscOptionsDestroy(&database_);
      throw;
    }
  }
  Options_scope(const Options_scope&) = delete;
  Options_scope& operator=(const Options_scope&) = delete;
  ~Options_scope()
  {
    PetscOptionsPop();
    PetscOptionsDestroy(&database_);
  }

private:
  PetscOptions database_ = nullptr;
};

// diag(d) with A's row distribution.
Petsc_mat diagonal_matrix(MPI_Comm comm, Mat A, Vec d)
{
  PetscInt local = 0, global = 0, first = 0, last = 0;
  TVF_PETSC(MatGetLocalSize(A, &local, nullptr));
  TVF_PETSC(MatGetSize(A, &global, nullptr));
  Petsc_mat B;
  TVF_PETSC(MatCreateAIJ(comm, local, local, global, global, 1, nullptr, 0, nullptr, B.address()));
  TVF_PETSC(VecGetOwnershipRange(d, &first, &last));
  const PetscScalar* values = nullptr;
  TVF_PETSC(VecGetArrayRead(d, &values));
  for(PetscInt i = first; i < last; ++i) TVF_PETSC(MatSetValue(B, i, i, values[i - first], INSERT_VALUES));
  TVF_PETSC(VecRestoreArrayRead(d, &values));
  TVF_PETSC(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  TVF_PETSC(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
  return B;
}

// The package's residual |D^-1/2 (A x - l D x)| / (l |D^1/2 x|), with PETSc's vectors so
// that the mpirun children compute it on their distributed vectors the same way.
class Residual
{
public:
  Residual(Mat A, Vec d) : A_(A), d_(d)
  {
    TVF_PETSC(VecDuplicate(d, sqrt_d_.address()));
    TVF_PETSC(VecCopy(d, sqrt_d_));
    TVF_PETSC(VecSqrtAbs(sqrt_d_));
    TVF_PETSC(VecDuplicate(d, inv_sqrt_d_.address()));
    TVF_PETSC(VecCopy(sqrt_d_, inv_sqrt_d_));
    TVF_PETSC(VecReciprocal(inv_sqrt_d_));
    TVF_PETSC(VecDuplicate(d, r_.address()));
    TVF_PETSC(VecDuplicate(d, t_.address()));
  }
  double operator()(double lambda, Vec x) const
  {
    PetscReal top = 0, bottom = 0;
    TVF_PETSC(MatMult(A_, x, r_));
    TVF_PETSC(VecPointwiseMult(t_, d_, x));
    TVF_PETSC(VecAXPY(r_, -lambda, t_));
    TVF_PETSC(VecPointwiseMult(r_, r_, inv_sqrt_d_));
    TVF_PETSC(VecNorm(r_, NORM_2, &top));
    TVF_PETSC(VecPointwiseMult(t_, sqrt_d_, x));
    TVF_PETSC(VecNorm(t_, NORM_2, &bottom));
    return top / (std::abs(lambda) * bottom);
  }

private:
  Mat A_;
  Vec d_;
  Petsc_vec sqrt_d_, inv_sqrt_d_, r_, t_;
};

// One SLEPc run on `comm` (one rank in this process, all ranks in a child).
Slepc_outcome solve_on(MPI_Comm comm, Mat A, Vec d, const std::vector<Petsc_vec>& kernel, const Slepc_settings& s)
{
  Slepc_outcome out;
  reset_peak_memory();
  const double resident = resident_bytes();
  Petsc_mat B = diagonal_matrix(comm, A, d);
  Options_scope options(slepc_options(s));
  Petsc_eps eps;
  TVF_PETSC(EPSCreate(comm, eps.address()));
  TVF_PETSC(EPSSetOperators(eps, A, B));
  TVF_PETSC(EPSSetProblemType(eps, EPS_GHEP));
  TVF_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
  if(s.method == Slepc_method::slicing)
  {
    TVF_PETSC(EPSSetWhichEigenpairs(eps, EPS_ALL));
    TVF_PETSC(EPSSetInterval(eps, s.lower, s.upper));
  }
  else
  {
    TVF_PETSC(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE));
    TVF_PETSC(EPSSetTarget(eps, -1.0));
    if(!kernel.empty())
    {
      std::vector<Vec> vectors(kernel.begin(), kernel.end());
      TVF_PETSC(EPSSetDeflationSpace(eps, static_cast<PetscInt>(vectors.size()), vectors.data()));
    }
  }
  TVF_PETSC(EPSSetFromOptions(eps));
  Petsc_vec x;
  TVF_PETSC(MatCreateVecs(A, x.address(), nullptr));

  TVF_MPI(MPI_Barrier(comm));
  const double start = MPI_Wtime();
  TVF_PETSC(EPSSolve(eps));
  PetscInt converged = 0;
  TVF_PETSC(EPSGetConverged(eps, &converged));
  PetscScalar lambda = 0;
  // The first call computes Krylov-Schur's eigenvectors: they belong to the solve.
  if(converged > 0) TVF_PETSC(EPSGetEigenpair(eps, 0, &lambda, nullptr, x, nullptr));
  TVF_MPI(MPI_Barrier(comm));
  out.seconds = MPI_Wtime() - start;

  EPSConvergedReason reason;
  TVF_PETSC(EPSGetConvergedReason(eps, &reason));
  if(reason < 0)
  {
    out.error = std::string("EPSSolve did not converge (") + EPSConvergedReasons[reason] + ")";
    return out;
  }
  const Residual residual(A, d);
  Eigen::VectorXd values(converged), residuals(converged);
  for(PetscInt i = 0; i < converged; ++i)
  {
    TVF_PETSC(EPSGetEigenpair(eps, i, &lambda, nullptr, x, nullptr));
    values[i] = PetscRealPart(lambda);
    residuals[i] = residual(values[i], x);
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(converged));
  std::iota(order.begin(), order.end(), Eigen::Index(0));
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return values[a] < values[b]; });
  out.values.resize(converged);
  out.residuals.resize(converged);
  for(Eigen::Index i = 0; i < converged; ++i)
  {
    out.values[i] = values[order[i]];
    out.residuals[i] = residuals[order[i]];
  }
  // A rank that cannot tell makes the sum negative: unknown.
  const double added = resident < 0 ? -1e300 : peak_memory_bytes() - resident;
  TVF_MPI(MPI_Allreduce(&added, &out.peak_bytes, 1, MPI_DOUBLE, MPI_SUM, comm));
  out.peak_bytes = std::max(out.peak_bytes, -1.0);
  out.ok = true;
  return out;
}

Petsc_mat to_petsc(const Eigen::SparseMatrix<double>& A)
{
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows = A;
  rows.makeCompressed();
  const PetscInt n = static_cast<PetscInt>(rows.rows());
  const std::vector<PetscInt> starts(rows.outerIndexPtr(), rows.outerIndexPtr() + n + 1);
  const std::vector<PetscInt> columns(rows.innerIndexPtr(), rows.innerIndexPtr() + rows.nonZeros());
  Petsc_mat M;
  TVF_PETSC(MatCreate(PETSC_COMM_SELF, M.address()));
  TVF_PETSC(MatSetSizes(M, n, n, n, n));
  TVF_PETSC(MatSetType(M, MATSEQAIJ));
  TVF_PETSC(MatSeqAIJSetPreallocationCSR(M, starts.data(), columns.data(), rows.valuePtr()));
  TVF_PETSC(MatSetOption(M, MAT_SYMMETRIC, PETSC_TRUE));
  return M;
}

Petsc_vec to_petsc(const Eigen::VectorXd& v)
{
  Petsc_vec x;
  TVF_PETSC(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(v.size()), x.address()));
  PetscScalar* values = nullptr;
  TVF_PETSC(VecGetArray(x, &values));
  std::copy(v.data(), v.data() + v.size(), values);
  TVF_PETSC(VecRestoreArray(x, &values));
  return x;
}

// The files a child reads (problem.bin: A then d; settings.txt) and writes (result.txt).
void write_settings(const std::string& path, const Slepc_settings& s)
{
  std::ofstream out(path);
  out.precision(17);
  out << (s.method == Slepc_method::slicing ? "slicing" : "krylov_schur") << " " << s.lower << " " << s.upper << " "
      << s.nev << " " << s.partitions << "\n"
      << s.extra_options << "\n";
  if(!out) throw std::runtime_error("cannot write " + path);
}

Slepc_settings read_settings(const std::string& path)
{
  std::ifstream in(path);
  Slepc_settings s;
  std::string method;
  in >> method >> s.lower >> s.upper >> s.nev >> s.partitions;
  in.ignore(1);
  std::getline(in, s.extra_options);
  if(!in || (method != "slicing" && method != "krylov_schur")) throw std::runtime_error("cannot read " + path);
  s.method = method == "slicing" ? Slepc_method::slicing : Slepc_method::krylov_schur;
  return s;
}

void write_outcome(const std::string& path, const Slepc_outcome& o)
{
  std::ofstream out(path);
  out.precision(17);
  out << (o.ok ? "ok" : "failed") << " " << o.seconds << " " << o.peak_bytes << " " << o.values.size() << "\n" << o.error << "\n";
  for(Eigen::Index i = 0; i < o.values.size(); ++i) out << o.values[i] << " " << o.residuals[i] << "\n";
  if(!out) throw std::runtime_error("cannot write " + path);
}

Slepc_outcome read_outcome(const std::string& path)
{
  std::ifstream in(path);
  Slepc_outcome o;
  std::string status;
  Eigen::Index count = 0;
  in >> status >> o.seconds >> o.peak_bytes >> count;
  in.ignore(1);
  std::getline(in, o.error);
  if(!in || count < 0) throw std::runtime_error("cannot read " + path);
  o.values.resize(count);
  o.residuals.resize(count);
  for(Eigen::Index i = 0; i < count; ++i) in >> o.values[i] >> o.residuals[i];
  if(!in) throw std::runtime_error("cannot read " + path + ": truncated");
  o.ok = status == "ok";
  return o;
}

std::vector<std::string> words(const std::string& text)
{
  std::istringstream in(text);
  std::vector<std::string> w;
  for(std::string word; in >> word;) w.push_back(word);
  return w;
}

std::string this_executable()
{
  std::vector<char> path(4096);
  const ssize_t length = readlink("/proc/self/exe", path.data(), path.size() - 1);
  if(length <= 0) throw std::runtime_error("cannot find this executable (/proc/self/exe)");
  return std::string(path.data(), static_cast<std::size_t>(length));
}

// Runs `arguments` with `environment`, returns its exit status.
int run_program(const std::vector<std::string>& arguments, const std::vector<std::string>& environment)
{
  std::vector<char*> argv, envp;
  for(const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for(const std::string& e : environment) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), envp.data());
  if(error != 0) throw std::runtime_error("cannot start " + arguments[0] + ": " + std::strerror(error));
  int status = 0;
  while(waitpid(pid, &status, 0) < 0)
    if(errno != EINTR) throw std::runtime_error("waitpid failed: " + std::string(std::strerror(errno)));
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

void set_variable(std::vector<std::string>& environment, const std::string& name, const std::string& value)
{
  environment.erase(std::remove_if(environment.begin(), environment.end(),
                                   [&](const std::string& e) { return e.compare(0, name.size() + 1, name + "=") == 0; }),
                    environment.end());
  environment.push_back(name + "=" + value);
}

} // namespace

std::string slepc_options(const Slepc_settings& s)
{
  std::ostringstream o;
  o << "-st_type sinvert -st_ksp_type preonly -st_pc_type cholesky -st_pc_factor_mat_solver_type mumps";
  if(s.method == Slepc_method::slicing)
  {
    // ICNTL(13) = 1: MUMPS's inertia is exact also in parallel (no ScaLAPACK root).
    // Sub-solvers of 20/40: SLEPc's defaults (40/80) left pairs at residuals of 8e-10.
    o << " -st_mat_mumps_icntl_13 1 -eps_krylovschur_nev 20 -eps_krylovschur_ncv 40";
    if(s.partitions > 1) o << " -eps_krylovschur_partitions " << s.partitions;
  }
  else
  {
    o << " -eps_nev ";
    if(s.nev > 0) o << s.nev;
    else o << "N+10"; // for the bench's header
    o << " -eps_mpd 256";
  }
  if(!s.extra_options.empty()) o << " " << s.extra_options;
  return o.str();
}

Slepc_session::Slepc_session()
{
  for(char** e = environ; *e; ++e) environment_.push_back(*e);
  TVF_PETSC(SlepcInitializeNoArguments());
}

Slepc_session::~Slepc_session() { SlepcFinalize(); }

Slepc_outcome Slepc_session::solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d,
                                   const Eigen::MatrixXd& kernel, const Slepc_settings& settings) const
{
  try
  {
    const Petsc_mat PA = to_petsc(A);
    const Petsc_vec Pd = to_petsc(d);
    std::vector<Petsc_vec> Pkernel;
    for(Eigen::Index j = 0; j < kernel.cols(); ++j) Pkernel.push_back(to_petsc(Eigen::VectorXd(kernel.col(j))));
    return solve_on(PETSC_COMM_SELF, PA, Pd, Pkernel, settings);
  }
  catch(const std::exception& e)
  {
    Slepc_outcome out;
    out.error = e.what();
    return out;
  }
}

Slepc_outcome Slepc_session::solve_with_mpirun(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d,
                                               const Slepc_settings& settings, int ranks,
                                               const std::string& mpirun) const
{
  namespace fs = std::filesystem;
  std::string folder = (fs::temp_directory_path() / "tvf_slepc_XXXXXX").string();
  if(!mkdtemp(&folder[0]))
  {
    Slepc_outcome out;
    out.error = "cannot make a temporary folder: " + std::string(std::strerror(errno));
    return out;
  }
  Slepc_outcome out;
  try
  {
    {
      const Petsc_mat PA = to_petsc(A);
      const Petsc_vec Pd = to_petsc(d);
      Petsc_viewer viewer;
      TVF_PETSC(PetscViewerBinaryOpen(PETSC_COMM_SELF, (folder + "/problem.bin").c_str(), FILE_MODE_WRITE,
                                      viewer.address()));
      TVF_PETSC(MatView(PA, viewer));
      TVF_PETSC(VecView(Pd, viewer));
    }
    write_settings(folder + "/settings.txt", settings);
    std::vector<std::string> arguments = words(mpirun);
    if(arguments.empty()) throw std::runtime_error("no mpirun command given");
    arguments.insert(arguments.end(), {"-np", std::to_string(ranks), this_executable(), "--slepc-child", folder});
    std::vector<std::string> environment = environment_;
    // One BLAS thread per rank: the ranks already fill the cores.
    set_variable(environment, "OPENBLAS_NUM_THREADS", "1");
    set_variable(environment, "OMP_NUM_THREADS", "1");
    if(geteuid() == 0) // Open MPI refuses root without these (other MPIs ignore them)
    {
      set_variable(environment, "OMPI_ALLOW_RUN_AS_ROOT", "1");
      set_variable(environment, "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1");
    }
    const auto start = std::chrono::steady_clock::now();
    const int status = run_program(arguments, environment);
    const double launch = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(status != 0) throw std::runtime_error(arguments[0] + " exited with status " + std::to_string(status));
    out = read_outcome(folder + "/result.txt");
    out.launch_seconds = launch;
  }
  catch(const std::exception& e)
  {
    out = Slepc_outcome();
    out.error = e.what();
  }
  std::error_code ignored;
  fs::remove_all(folder, ignored);
  return out;
}

int slepc_child_main(const std::string& dir)
{
  if(SlepcInitializeNoArguments() != 0)
  {
    std::fprintf(stderr, "bench_spectral --slepc-child: SlepcInitialize failed\n");
    return 1;
  }
  try
  {
    const Slepc_settings settings = read_settings(dir + "/settings.txt");
    Petsc_viewer viewer;
    TVF_PETSC(PetscViewerBinaryOpen(PETSC_COMM_WORLD, (dir + "/problem.bin").c_str(), FILE_MODE_READ, viewer.address()));
    Petsc_mat A;
    TVF_PETSC(MatCreate(PETSC_COMM_WORLD, A.address()));
    TVF_PETSC(MatSetType(A, MATAIJ));
    TVF_PETSC(MatLoad(A, viewer));
    TVF_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    Petsc_vec d;
    TVF_PETSC(MatCreateVecs(A, d.address(), nullptr));
    TVF_PETSC(VecLoad(d, viewer));
    const Slepc_outcome out = solve_on(PETSC_COMM_WORLD, A, d, {}, settings);
    PetscMPIInt rank = 0;
    TVF_MPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    if(rank == 0) write_outcome(dir + "/result.txt", out);
  }
  catch(const std::exception& e)
  {
    // One rank's failure would leave the others waiting in a collective call.
    std::fprintf(stderr, "bench_spectral --slepc-child: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 1);
  }
  return SlepcFinalize() == 0 ? 0 : 1;
}

} // namespace tvf_bench
