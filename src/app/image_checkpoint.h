// The checkpoints of one camera's render (--checkpoint, --resume, an interrupt): the
// key of everything that changes its pixels, the saved film it continues from, the partial
// image and checkpoint written between passes, and the outputs written at its end.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "integrator/render_scheduler.h"
#include "io/checkpoint.h"
#include "render_job.h"

namespace rt {

class ImageCheckpoint {
 public:
  // Camera `camera` of `scene`, prepared for `device`. With --resume or --skip-existing,
  // reads its <image>.rtcheckpoint when there is one; throws std::runtime_error (one line
  // naming the first field that differs) when that was made with other settings, or when
  // its rows hold different sample counts (a distributed render's, io/checkpoint.h) unless
  // `bands_allowed` (a distributed rank, which continues each band from its own count).
  ImageCheckpoint(const CliOptions& opt, const JobScene& scene, int camera,
                  const PreparedScene& prepared, const RenderDevice& device,
                  bool bands_allowed = false);

  // The hooks of render_camera: the saved film to start from, and with --checkpoint the
  // saves between passes, each at the end of the first pass S or more seconds after the
  // last save (or the start), and passes no longer than S.
  const PassHooks* hooks(RenderDevice& device);
  // The saved film alone, without the saves between passes: a distributed rank renders
  // only a band of the image, which rank 0 writes (distributed/tile_worker.cpp).
  PassHooks resume_only() const {
    PassHooks h = hooks_;
    h.after_pass = nullptr;
    h.pass_seconds = 0;
    return h;
  }
  // The samples every pixel of the saved film holds (0 without one): the progress starts there.
  int start_sample() const { return hooks_.start_sample; }
  // The samples each row of the saved film holds (empty: every row holds resume_only()'s
  // start_sample).
  const std::vector<int>& saved_rows() const { return saved_.row_spp; }
  // Everything that changes the film's bytes; rank 0 of a distributed render writes its
  // checkpoints with the key the rendering rank made.
  const CheckpointKey& key();

  // Writes the render's outputs: an interrupted one's (fewer samples than asked) marked
  // partial, with its checkpoint beside them when checkpoints are asked for (--checkpoint,
  // --resume, a render continued from one; a plain interrupt leaves no other file); a
  // finished one's without a mark, its checkpoint removed. Returns the checkpoint's path
  // when one was written, else "".
  std::string finish(const RenderResult& r, bool interrupted);

 private:
  void save(RenderDevice& device, int spp, double since_last);
  bool keeps_checkpoints() const { return opt_.checkpoint_s > 0 || opt_.resume || saved_.spp > 0; }
  void write(const RenderResult& r, bool partial);

  const CliOptions& opt_;
  const JobScene& scene_;
  int camera_;
  const PreparedScene& prepared_;
  std::string device_name_, image_, path_;
  int asked_ = 0;
  CheckpointKey key_;
  Checkpoint saved_;
  PassHooks hooks_;
  std::chrono::steady_clock::time_point last_save_;
};

}  // namespace rt
