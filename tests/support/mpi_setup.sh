# Sourced by the mpirun test scripts after they set $rt (the raytracer) and $device (cpu or
# cl): Open MPI allowed as root and kept on the loopback (no network interface is probed, so
# containers need no setup), the one-line fail(), and the skip when OpenCL is asked for but
# no device is usable.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl=self,vader

fail() {
  echo "FAIL: $*"
  exit 1
}
if [ "$device" = cl ] && ! "$rt" --list-devices > /dev/null 2>&1; then
  echo "SKIP: no OpenCL device"
  exit 77
fi
