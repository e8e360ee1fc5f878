// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_INDEPENDENT_PARTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_INDEPENDENT_PARTS_H

// The independent parts of an untangling problem (region_problem.h). Its regions are often far apart (the
// shared 302K-face bunny's polish: 144 parts, 63K reduced variables): no face and no variable couples two parts,
// so the energy is a sum over them and N^T H N is block diagonal. Each part is then its own problem (untangler.h):
// its own block factored, its own eps continuation, flip-free step bound, backtracking and stopping test. Solved
// together, one step would be bounded by the part nearest its barrier, one eps would serve every part, and every
// part would take as many steps as the slowest (the bunny's polish: 50 steps, the cap, for all 144 parts); and a
// part that has stopped is neither factored nor evaluated again.
// With two threads (number_of_threads), the parts are dealt into two halves of about as many faces, and a pass
// (energy, Newton directions, line search) runs the halves at once where each has enough faces to step: a part's
// numbers are computed by one thread, in the same order as on one thread, so the results are the same bits.

#include <CGAL/Seamless_snapping/internal/threads.h>
#include <CGAL/Seamless_snapping/internal/untangling/region_problem.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// A symmetric matrix stored as the upper triangle of P M P^T, P its fill-reducing order (AMD), and its LDL^T: the
// order is applied once to the pattern instead of to the values at every factorization (Eigen's SimplicialLDLT with
// AMDOrdering permutes M each time: about 3 % of the untangling of the 302K-face bunny of ../shared/large). The same
// order, the same matrix handed to the same factorization, the same solves: the same bits.
struct Permuted_ldlt
{
  Region_problem::Matrix M;                           // upper triangle of P M P^T
  std::vector<int> diagonal;                          // per stored diagonal entry, in the order of the unpermuted M's
                                                      // columns: its place in M's values
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P, Pinv;
  Eigen::SimplicialLDLT<Region_problem::Matrix, Eigen::Upper, Eigen::NaturalOrdering<int> > ldlt;

  // from the lower triangle `lower` of M (pattern); `moved`: per value of M, the index of the value of `lower` it holds
  void analyze(const Region_problem::Matrix& lower, std::vector<int>& moved)
  {
    const Eigen::Index m = lower.rows();
    {
      Region_problem::Matrix full;
      full = lower.selfadjointView<Eigen::Lower>();     // as Eigen's ordering step does
      Eigen::AMDOrdering<int> amd;
      amd(full, Pinv);
    }
    P = Pinv.inverse();
    Region_problem::Matrix tagged = lower;              // values: their own indices (exact in double)
    for(Eigen::Index k = 0; k < tagged.nonZeros(); ++k) tagged.valuePtr()[k] = double(k);
    M.resize(m, m);
    M.selfadjointView<Eigen::Upper>() = tagged.selfadjointView<Eigen::Lower>().twistedBy(P);
    std::vector<int> position(std::size_t(lower.nonZeros()), -1);
    moved.resize(std::size_t(M.nonZeros()));
    for(Eigen::Index q = 0; q < M.nonZeros(); ++q) {
      moved[std::size_t(q)] = int(M.valuePtr()[q]);
      position[std::size_t(moved[std::size_t(q)])] = int(q);
      M.valuePtr()[q] = 0;
    }
    diagonal.clear();
    for(Eigen::Index j = 0; j < m; ++j)
      for(int k = lower.outerIndexPtr()[j]; k < lower.outerIndexPtr()[j + 1]; ++k)
        if(lower.innerIndexPtr()[k] == j) diagonal.push_back(position[std::size_t(k)]);
    ldlt.analyzePattern(M);
  }

  // x = M^-1 b (unpermuted), from the last factorization
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const
  {
    Eigen::VectorXd x = P * b;
    x = ldlt.solve(x);
    return Pinv * x;
  }
};

// d = -(M + mu I)^-1 g for the smallest mu = s, 100 s, ..., 1e10 s (s = 1e-10 times the mean diagonal) for
// which the LDL^T of M + mu I succeeds (a small shift makes a PSD matrix definite); M holds the PSD Hessian
// and keeps the shift. Steepest descent if none factors. True if d is a descent direction.
inline bool shifted_newton_solve(Permuted_ldlt& F, const Eigen::VectorXd& g, Eigen::VectorXd& d)
{
  double trace = 0;
  for(int k : F.diagonal) trace += F.M.valuePtr()[k];
  const double shift = 1e-10 * (trace > 0 ? trace / double(g.size()) : 1.);
  double added = 0;
  for(double mu = shift; mu <= 1e10 * shift; mu *= 100) {
    for(int k : F.diagonal) F.M.valuePtr()[k] += mu - added;
    added = mu;
    F.ldlt.factorize(F.M);
    if(F.ldlt.info() == Eigen::Success) { d = F.solve(-g); if(d.allFinite()) return g.dot(d) < 0; }
  }
  d = -g;
  return g.dot(d) < 0;
}

class Independent_parts
{
public:
  std::vector<int> of_w, of_face, of_var;   // Region_problem::components()
  int n = 0;
  std::vector<std::size_t> faces;           // per part: its number of faces

  // the parts of p, each with the pattern of its block of p.H analysed once; `threads` >= 2: see the header
  explicit Independent_parts(const Region_problem& p, unsigned threads = 1)
    : threads_(threads)
  {
    n = p.components(of_w, of_face, of_var);
    faces.assign(std::size_t(n), 0);
    for(int c : of_face) if(c >= 0) ++faces[std::size_t(c)];
    half_.assign(std::size_t(n), 0);                 // the larger parts first, each to the half with fewer faces so far
    std::vector<int> order(static_cast<std::size_t>(n));
    for(int c = 0; c < n; ++c) order[std::size_t(c)] = c;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return faces[std::size_t(a)] > faces[std::size_t(b)]; });
    std::size_t load[2] = {0, 0};
    for(int c : order) {
      const int h = load[1] < load[0] ? 1 : 0;
      half_[std::size_t(c)] = char(h);
      load[h] += faces[std::size_t(c)];
    }
    std::vector<int> local(of_w.size());
    for(int c = 0; c < n; ++c) blocks_.emplace_back(new Block);
    for(std::size_t i = 0; i < of_w.size(); ++i) {
      Block& b = *blocks_[std::size_t(of_w[i])];
      local[i] = int(b.w.size());
      b.w.push_back(int(i));
    }
    std::vector<std::vector<int> > outer(std::size_t(n), std::vector<int>(1, 0));
    std::vector<std::vector<int> > inner((std::size_t(n)));
    const Region_problem::Matrix& H = p.H;
    for(Eigen::Index col = 0; col < H.outerSize(); ++col) {   // the columns of a part keep their order, so do its rows
      const std::size_t c = std::size_t(of_w[std::size_t(col)]);
      Block& b = *blocks_[c];
      for(int k = H.outerIndexPtr()[col]; k < H.outerIndexPtr()[col + 1]; ++k) {
        const int row = H.innerIndexPtr()[k];
        inner[c].push_back(local[std::size_t(row)]);
        b.source.push_back(k);
      }
      outer[c].push_back(int(inner[c].size()));
    }
    for(std::size_t c = 0; c < std::size_t(n); ++c) {
      Block& b = *blocks_[c];
      const std::vector<double> zeros(inner[c].size(), 0.);
      const Eigen::Index m = Eigen::Index(b.w.size());
      const Region_problem::Matrix lower =
        Eigen::Map<const Region_problem::Matrix>(m, m, Eigen::Index(zeros.size()), outer[c].data(), inner[c].data(), zeros.data());
      std::vector<int> moved;
      b.F.analyze(lower, moved);
      std::vector<int> source(moved.size());
      for(std::size_t q = 0; q < moved.size(); ++q) source[q] = b.source[std::size_t(moved[q])];
      b.source.swap(source);
    }
  }

  static bool any(const std::vector<char>& flags) { return std::find(flags.begin(), flags.end(), 1) != flags.end(); }

  // the face evaluations of one pass over the parts with `which` set
  double work(const std::vector<char>& which) const
  {
    double w = 0;
    for(std::size_t c = 0; c < std::size_t(n); ++c) w += which[c] ? double(faces[c]) : 0.;
    return w;
  }

  // the energy (Region_problem::group_values()) of the parts with `which` set, per part
  void values(const Region_problem& p, const std::vector<double>& w, const std::vector<double>& eps, double weight,
              const std::vector<char>& which, std::vector<double>& E, std::vector<double>& D,
              std::vector<std::size_t>* non_positive = nullptr) const
  {
    std::vector<double> E1, D1;
    std::vector<std::size_t> bad1;
    if(!in_halves(which, [&](const std::vector<char>& part, int h) {
         values_of(p, w, eps, weight, part, h ? E1 : E, h ? D1 : D, h && non_positive != nullptr ? &bad1 : non_positive);
       }))
      return;
    take_second_half(E1, E);
    take_second_half(D1, D);
    if(non_positive != nullptr) take_second_half(bad1, *non_positive);
  }

  // One Newton direction d of the energy per part with `which` set (0 elsewhere), and per part its slope g.d;
  // a part with no descent is unset in `which`. refactor = false: each part's last factorization is used where it
  // gives a descent (a fixed positive definite matrix: the line search still decreases the energy), and the
  // Hessian is assembled and factored only for the parts where it does not
  void newton_directions(Region_problem& p, const std::vector<double>& w, const std::vector<double>& eps, double weight,
                         bool refactor, std::vector<char>& which, Eigen::VectorXd& d, std::vector<double>& slope)
  {
    Eigen::VectorXd d1;
    std::vector<double> slope1;
    if(!in_halves(which, [&](std::vector<char>& part, int h) {
         directions_of(p, w, eps, weight, refactor, part, h ? d1 : d, h ? slope1 : slope);
       }))
      return;
    for(std::size_t i = 0; i < of_w.size(); ++i) if(half_[std::size_t(of_w[i])]) d[Eigen::Index(i)] = d1[Eigen::Index(i)];
    take_second_half(slope1, slope);
  }

  // Armijo backtracking of every part c with `which` set from its step t[c] along d; a part moves if its energy
  // E[c] decreases enough (E[c] and D[c], its smallest det J, are then those at the new w), and is unset in
  // `which` when it cannot or when the decrease is at most `tolerance` (relative). Returns the face evaluations.
  double line_search(const Region_problem& p, std::vector<double>& w, const Eigen::VectorXd& d, const std::vector<double>& slope,
                     const std::vector<double>& t, const std::vector<double>& eps, double weight, double tolerance,
                     std::vector<char>& which, std::vector<double>& E, std::vector<double>& D) const
  {
    std::vector<double> E1 = E, D1 = D;               // each half writes only its parts' entries of w
    double evaluations[2] = {0, 0};
    if(in_halves(which, [&](std::vector<char>& part, int h) {
         evaluations[h] = search_of(p, w, d, slope, t, eps, weight, tolerance, part, h ? E1 : E, h ? D1 : D, trial_[h]);
       })) {
      take_second_half(E1, E);
      take_second_half(D1, D);
    }
    return evaluations[0] + evaluations[1];            // counts of faces: exact in any order
  }

  // per part c with `which` set, t[c] min= the largest step along d that keeps its faces above det J = floor
  // (Region_problem::group_positive_steps())
  void positive_steps(const Region_problem& p, const std::vector<double>& w, const Eigen::VectorXd& d, double floor,
                      const std::vector<char>& which, std::vector<double>& t) const
  {
    std::vector<double> t1 = t;
    if(in_halves(which, [&](const std::vector<char>& part, int h) {
         p.group_positive_steps(w, d, floor, masked(of_face, part), h ? t1 : t);
       }))
      take_second_half(t1, t);
  }

  // the groups of the parts with `keep` set (-1 elsewhere), for Region_problem's group functions
  std::vector<int> masked(const std::vector<int>& group, const std::vector<char>& keep) const
  {
    std::vector<int> m(group.size());
    for(std::size_t i = 0; i < group.size(); ++i) m[i] = group[i] >= 0 && keep[std::size_t(group[i])] ? group[i] : -1;
    return m;
  }

private:
  // A pass runs its two halves at once when each has at least this many faces in the parts it steps (a thread's
  // start costs about as much as a pass over a few hundred faces; against 2000: duck_qc_8's untangling 211 -> 198 ms,
  // the dragon's and the 302K-face bunny's the same within their noise)
  static constexpr std::size_t min_half_faces = 500;

  // A pass over the parts with `which` set: pass(which, 0) on one thread, or, where each half has enough faces to
  // step, pass(first, 0) and pass(second, 1) at once on the two halves of `which`, whose flags (a pass may unset
  // some) are then those of `which` again. Returns whether it ran the halves; the caller then takes the second
  // half's outputs from where pass(., 1) wrote them.
  template <class Which, class Pass>
  bool in_halves(Which& which, const Pass& pass) const
  {
    std::size_t load[2] = {0, 0};
    for(std::size_t c = 0; c < std::size_t(n); ++c) if(which[c]) load[int(half_[c])] += faces[c];
    if(threads_ < 2 || (std::min)(load[0], load[1]) < min_half_faces) { pass(which, 0); return false; }
    std::vector<char> halves[2] = {which, which};
    for(std::size_t c = 0; c < std::size_t(n); ++c) halves[half_[c] ? 0 : 1][c] = 0;
    run_concurrently(2, [&] { pass(halves[0], 0); }, [&] { pass(halves[1], 1); });
    if constexpr(!std::is_const<Which>::value)
      for(std::size_t c = 0; c < std::size_t(n); ++c) which[c] = halves[int(half_[c])][c];
    return true;
  }

  // per part c of the second half: to[c] = from[c]
  template <class T>
  void take_second_half(const std::vector<T>& from, std::vector<T>& to) const
  {
    for(std::size_t c = 0; c < std::size_t(n); ++c) if(half_[c]) to[c] = from[c];
  }

  void values_of(const Region_problem& p, const std::vector<double>& w, const std::vector<double>& eps, double weight,
                 const std::vector<char>& which, std::vector<double>& E, std::vector<double>& D,
                 std::vector<std::size_t>* non_positive) const
  {
    E.assign(std::size_t(n), 0.);
    D.assign(std::size_t(n), HUGE_VAL);
    if(non_positive != nullptr) non_positive->assign(std::size_t(n), 0);
    p.group_values(w, eps, weight, masked(of_face, which), masked(of_var, which), E, D, non_positive);
  }

  // the values of p.H in the blocks of the parts with `which` set, to 0 (Region_problem::derivatives() adds to them)
  void zero_hessian(Region_problem& p, const std::vector<char>& which) const
  {
    for(std::size_t c = 0; c < std::size_t(n); ++c)
      if(which[c]) for(int k : blocks_[c]->source) p.H.valuePtr()[k] = 0;
  }

  void directions_of(Region_problem& p, const std::vector<double>& w, const std::vector<double>& eps, double weight,
                     bool refactor, std::vector<char>& which, Eigen::VectorXd& d, std::vector<double>& slope)
  {
    Eigen::VectorXd g(Eigen::Index(w.size()));
    d = Eigen::VectorXd::Zero(Eigen::Index(w.size()));
    slope.assign(std::size_t(n), 0.);
    std::vector<int> todo;
    const std::vector<int> face_groups = masked(of_face, which), var_groups = masked(of_var, which);
    if(refactor) zero_hessian(p, which);
    p.derivatives(w, eps, weight, face_groups, var_groups, g, refactor);
    for(int c = 0; c < n; ++c) {
      if(!which[std::size_t(c)]) continue;
      Block& b = *blocks_[std::size_t(c)];
      if(!refactor && b.factored) {
        const Eigen::VectorXd gc = gather(b, g), dc = b.F.solve(-gc);
        if(dc.allFinite() && gc.dot(dc) < 0) { scatter(b, dc, d); continue; }
      }
      todo.push_back(c);
    }
    if(!refactor && !todo.empty()) {                   // the Hessian after all
      zero_hessian(p, which);
      p.derivatives(w, eps, weight, face_groups, var_groups, g, true);
    }
    for(int c : todo) {
      Block& b = *blocks_[std::size_t(c)];
      for(std::size_t k = 0; k < b.source.size(); ++k) b.F.M.valuePtr()[k] = p.H.valuePtr()[b.source[k]];
      Eigen::VectorXd dc;
      b.factored = shifted_newton_solve(b.F, gather(b, g), dc) && b.F.ldlt.info() == Eigen::Success;
      scatter(b, dc, d);
    }
    for(std::size_t c = 0; c < std::size_t(n); ++c) {
      if(!which[c]) continue;
      for(int i : blocks_[c]->w) slope[c] += g[i] * d[i];
      if(!(slope[c] < 0)) which[c] = 0;
    }
  }

  // line_search() of the parts with `which` set; reads and writes the entries of w of those parts only (and of
  // `trial`, the half's buffer of the size of w)
  double search_of(const Region_problem& p, std::vector<double>& w, const Eigen::VectorXd& d, const std::vector<double>& slope,
                   std::vector<double> t, const std::vector<double>& eps, double weight, double tolerance,
                   std::vector<char>& which, std::vector<double>& E, std::vector<double>& D, std::vector<double>& trial) const
  {
    std::vector<char> pending = which, accepted;
    std::vector<double> E_new, D_new;                  // the energy of the pending parts reads only their entries of trial
    trial.resize(w.size());
    double evaluations = 0;
    for(int ls = 0; ls < 40 && any(pending); ++ls) {
      for(std::size_t c = 0; c < std::size_t(n); ++c)
        if(pending[c]) for(int i : blocks_[c]->w) trial[std::size_t(i)] = w[std::size_t(i)] + t[c] * d[i];
      evaluations += work(pending);
      values_of(p, trial, eps, weight, pending, E_new, D_new, nullptr);
      accepted.assign(std::size_t(n), 0);
      for(std::size_t c = 0; c < std::size_t(n); ++c) {
        if(!pending[c]) continue;
        if(E_new[c] <= E[c] + 1e-4 * t[c] * slope[c]) {
          pending[c] = 0;
          accepted[c] = 1;
          if(E[c] - E_new[c] <= tolerance * std::fabs(E_new[c])) which[c] = 0;
          E[c] = E_new[c];
          D[c] = D_new[c];
        } else {
          t[c] *= 0.5;
        }
      }
      for(std::size_t c = 0; c < std::size_t(n); ++c)
        if(accepted[c]) for(int i : blocks_[c]->w) w[std::size_t(i)] = trial[std::size_t(i)];
    }
    for(std::size_t c = 0; c < std::size_t(n); ++c) if(pending[c]) which[c] = 0;   // no decrease found
    return evaluations;
  }

  struct Block
  {
    std::vector<int> w;                 // the part's w, increasing
    std::vector<int> source;            // per value of F.M: its index in the values of Region_problem::H
    Permuted_ldlt F;                    // the part's block of H and its factorization
    bool factored = false;
  };

  static Eigen::VectorXd gather(const Block& b, const Eigen::VectorXd& v)
  {
    Eigen::VectorXd out(Eigen::Index(b.w.size()));
    for(std::size_t i = 0; i < b.w.size(); ++i) out[Eigen::Index(i)] = v[b.w[i]];
    return out;
  }
  static void scatter(const Block& b, const Eigen::VectorXd& v, Eigen::VectorXd& out)
  {
    for(std::size_t i = 0; i < b.w.size(); ++i) out[b.w[i]] = v[Eigen::Index(i)];
  }

  std::vector<std::unique_ptr<Block> > blocks_;
  unsigned threads_ = 1;
  std::vector<char> half_;              // per part: the half it belongs to (0 or 1)
  mutable std::vector<double> trial_[2];// per half: the trial w of its line searches (search_of())
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_INDEPENDENT_PARTS_H
