// The Eigen decompositions of dynamic double matrices, compiled once (model/src/
// eigen_decompositions.cc) instead of in every file that uses one (JacobiSVD alone
// cost ~10 s of compile time in each of least_squares.cc, closed_loop_iv.cc and
// velocity_estimation.cc; docs/performance.md, "Compile time"). The precompiled header of every
// library and program includes it (CMakeLists.txt, uuvplan_pch), so no source needs to; without
// precompiled headers (-DUUVPLAN_PCH=OFF) each file instantiates what it uses, as before.
#pragma once

#include <Eigen/Dense>

extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
extern template class Eigen::HouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>;
extern template class Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>;
extern template class Eigen::LDLT<Eigen::MatrixXd>;
extern template class Eigen::LLT<Eigen::MatrixXd>;
extern template class Eigen::FullPivLU<Eigen::MatrixXd>;
extern template class Eigen::PartialPivLU<Eigen::MatrixXd>;
