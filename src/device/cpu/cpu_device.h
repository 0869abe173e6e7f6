// The CPU reference: the kernel's code (cl/) compiled as C++, run on host threads.
#pragma once

#include "device/cpu/cpu_kernel.h"
#include "device/device.h"

namespace rt {

class CpuDevice final : public RenderDevice {
 public:
  // `threads` <= 0: all cores. The image does not depend on the count.
  explicit CpuDevice(int threads);
  std::string name() const override { return "cpu-reference"; }
  bool has_double() const override { return true; }
  void check_memory(const MemoryNeed& need) const override;
  DeviceLoadInfo load(const FlatScene& flat, const KernelConfig& kernel) override;
  uint64_t render(const RenderWork& work) override;
  void read_accum(std::vector<PixelAccum>* accum) override { *accum = accum_; }
  void read_primary(std::vector<PrimaryInfo>* primary) override { *primary = primary_; }
  void write_film(const std::vector<PixelAccum>& accum,
                  const std::vector<PrimaryInfo>& primary) override;

 private:
  int threads_;
  const FlatScene* flat_ = nullptr;
  CpuPixelFunction accumulate_ = nullptr;
  SceneData view_{};
  std::vector<PixelAccum> accum_;
  std::vector<PrimaryInfo> primary_;
};

}  // namespace rt
