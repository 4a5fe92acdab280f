#pragma once
#include <cstdint>
#include <string>

#include <Eigen/Geometry>

namespace hdprior {

// The checks every trajectory file format (TUM, KITTI, a times file) applies to one field; each
// throws Error(where, reason), `where` being "<file>:<line>".

// How far a quaternion's norm may be from 1, and a KITTI rotation from orthonormal.
constexpr double kRotationTolerance = 1e-3;

// A number that is finite: "'x' is not a number (field tx)", "tx is not finite (nan)".
double finiteField(const std::string& text, const char* name, const std::string& where);

// A timestamp in seconds, read exactly to nanoseconds, after `previous` when given.
int64_t timestampField(const std::string& text, const std::string& where, const int64_t* previous);

// A quaternion within 1e-3 of unit length, normalised.
Eigen::Quaterniond checkedQuaternion(const Eigen::Quaterniond& q, const std::string& where);

// A 3x3 matrix within 1e-3 of a rotation (|R^T R - I| per element, determinant > 0), as the nearest
// unit quaternion.
Eigen::Quaterniond checkedRotation(const Eigen::Matrix3d& R, const std::string& where);

}  // namespace hdprior
