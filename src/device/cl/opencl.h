// The OpenCL C++ wrapper as every host file uses it: errors are exceptions (cl::Error).
// Included instead of <CL/opencl.hpp> so every translation unit sees the same definitions.
#pragma once

#ifndef CL_HPP_ENABLE_EXCEPTIONS
#define CL_HPP_ENABLE_EXCEPTIONS
#endif
#include <CL/opencl.hpp>

#include <string>

namespace rt {

// "clBuildProgram failed (CL_BUILD_PROGRAM_FAILURE)": the failed call and its code's name.
std::string describe_cl_error(const cl::Error& e);

// A device or platform string without the trailing NULs and blanks drivers leave in them.
std::string clean_cl_string(std::string s);

}  // namespace rt
