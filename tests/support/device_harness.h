// The device harness of the tests: renders a flattened scene on a named device through the
// same scheduler as the executable, so tests never branch between devices by hand.
#pragma once

#include <string>

#include "device/device.h"
#include "integrator/render_scheduler.h"

namespace rt::test {

// One device per (kind, generic kernel, disk cache) for the whole test binary, since
// building programs is the slow part. Device::kCpu is always available; Device::kOpenCl
// returns nullptr with *why set (one line) when no OpenCL device is usable.
RenderDevice* shared_device(Device kind, std::string* why, bool generic_kernel = false,
                            bool kernel_cache = true);

// RT_TEST_PRECISION=double in the environment: every render of the harness runs the
// shared math in double (--precision double), so a whole suite can be rerun at that
// precision (README: precision).
bool test_precision_double();

// Renders on `device` with progress off, with the kernel `kernel` configures (in double when
// test_precision_double()).
RenderResult render_on(RenderDevice& device, const FlatScene& flat, const StopRule& stop = {},
                       DeviceLoadInfo* load_info = nullptr, const KernelConfig& kernel = {});

// Renders on a fresh CPU reference of `threads` threads (0: all cores).
RenderResult render_cpu(const FlatScene& flat, int threads = 0, const StopRule& stop = {},
                        const KernelConfig& kernel = {});

// Camera `camera` of `scene` prepared for `device` as the executable prepares it
// (prepare_for_device, then prepare_camera).
PreparedScene prepare_on(const RenderDevice& device, const SceneDesc& scene, int camera,
                         const RenderOptions& options);

// The sample count every pixel of `r` holds, or -1 when they differ (the stop rules stop
// between passes only, so every pixel must hold the same).
int common_sample_count(const RenderResult& r);

// "cpu" or "cl", for test names and messages.
const char* device_label(Device kind);

}  // namespace rt::test
