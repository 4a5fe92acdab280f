#include "engine/io/trajectory_checks.h"

#include <cmath>
#include <cstdio>

#include "engine/error.h"
#include "engine/io/seconds_text.h"
#include "engine/io/text_lines.h"

namespace hdprior {
namespace {

std::string shortNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// At most 40 characters of a field, for messages about arbitrary input.
std::string quoted(const std::string& text) { return "'" + (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "'"; }

}  // namespace

double finiteField(const std::string& text, const char* name, const std::string& where) {
  const std::optional<double> v = parseNumber(text);
  if (!v) throw Error(where, quoted(text) + " is not a number (field " + name + ")");
  if (!std::isfinite(*v)) throw Error(where, std::string(name) + " is not finite (" + text + ")");
  return *v;
}

int64_t timestampField(const std::string& text, const std::string& where, const int64_t* previous) {
  const std::optional<int64_t> t = parseSecondsNs(text);
  if (!t) throw Error(where, "bad timestamp " + quoted(text) + " (expected seconds, e.g. 1317384506.123456789)");
  if (previous && *t <= *previous) {
    throw Error(where, "timestamp " + formatSecondsNs(*t) + " s is not after the previous pose's " + formatSecondsNs(*previous) +
                           " s (timestamps must strictly increase)");
  }
  return *t;
}

Eigen::Quaterniond checkedQuaternion(const Eigen::Quaterniond& q, const std::string& where) {
  const double norm = q.norm();
  if (!(std::abs(norm - 1.0) <= kRotationTolerance)) {
    throw Error(where, "the quaternion's norm is " + shortNumber(norm) + " (more than 1e-3 from unit length)");
  }
  return q.normalized();
}

Eigen::Quaterniond checkedRotation(const Eigen::Matrix3d& R, const std::string& where) {
  const double error = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(error <= kRotationTolerance) || !(R.determinant() > 0.0)) {
    throw Error(where, "the 3x3 part is not a rotation (|R^T R - I| up to " + shortNumber(error) + ", determinant " +
                           shortNumber(R.determinant()) + "; at most 1e-3 and positive)");
  }
  return Eigen::Quaterniond(R).normalized();
}

}  // namespace hdprior
