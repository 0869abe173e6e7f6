#include "image/jpeg_error.h"

namespace rt {
namespace {

void on_jpeg_error(j_common_ptr cinfo) {
  JpegError* err = reinterpret_cast<JpegError*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, err->message);
  std::longjmp(err->jump, 1);
}

}  // namespace

jpeg_error_mgr* jpeg_error_jump(JpegError* err) {
  jpeg_error_mgr* mgr = jpeg_std_error(&err->mgr);
  mgr->error_exit = on_jpeg_error;
  return mgr;
}

}  // namespace rt
