// libjpeg's error handling, shared by the JPEG reader (image/read_ldr.cpp) and writer
// (io/jpeg_io.cpp): a fatal error must not return, so it jumps back to the caller's setjmp
// with the message kept for the one-line error.
#pragma once

// jpeglib.h needs FILE and size_t declared before it.
#include <csetjmp>
#include <cstdio>
#include <cstdlib>

#include <jpeglib.h>

namespace rt {

struct JpegError {
  jpeg_error_mgr mgr;  // First: libjpeg's cinfo->err points here.
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

// Installs the handler on `err` and returns what cinfo.err takes.
jpeg_error_mgr* jpeg_error_jump(JpegError* err);

}  // namespace rt
