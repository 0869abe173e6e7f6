#include "precision.h"

namespace rt {

Precision resolve_precision(Precision asked, bool device_has_fp64, const std::string& device_name,
                            std::string* notice) {
  notice->clear();
  if (asked != Precision::kAuto) return asked;
  if (device_has_fp64) return Precision::kDouble;
  *notice = "--precision auto: " + device_name +
            " has no double precision (cl_khr_fp64); rendering in float";
  return Precision::kFloat;
}

}  // namespace rt
