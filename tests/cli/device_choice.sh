#!/usr/bin/env bash
# Choosing the OpenGL device: --require-gpu refuses a software renderer with status 1 (here, on
# llvmpipe; on a GPU it runs), CSM_EGL_DEVICE with a device that does not exist is an error that
# lists the devices, and one that exists is used.
set -u
bin=$1
src=$2
. "$(dirname "$0")/lib/expect.sh"

if "$bin" --info | grep -q "(software)"; then
  expect 1 "--require-gpu: the OpenGL context" -- --headless --no-render --frames 1 --require-gpu \
    --set hairstyle.strands=20
  expect 1 "is a software renderer, not a GPU" -- --info --require-gpu
  # Without it, a warning that says so and how to make it an error.
  expect 0 "warning: OpenGL runs on a software renderer" -- --headless --no-render --frames 1 \
    --set hairstyle.strands=20
  # The CPU solver without drawing needs no context: nothing to refuse.
  expect 0 "" -- --headless --no-render --solver cpu --frames 1 --require-gpu \
    --set hairstyle.strands=20
else
  expect 0 "" -- --info --require-gpu
fi
CSM_EGL_DEVICE=97 expect 1 "CSM_EGL_DEVICE=97: no EGL device has that" -- --info
CSM_EGL_DEVICE=97 expect 1 "the devices are:" -- --headless --no-render --frames 1
CSM_EGL_DEVICE=no-such-gpu expect 1 "CSM_EGL_DEVICE=no-such-gpu: no EGL device's name" -- --info
CSM_EGL_DEVICE=0 CSM_EGL_PLATFORM=surfaceless expect 1 "is not device" -- --info
# The first device EGL lists, chosen by its place (or CUDA index), says so in the context line.
if CSM_EGL_PLATFORM=device "$bin" --info >/dev/null 2>&1; then
  CSM_EGL_DEVICE=0 expect 0 "context:                    EGL device" -- --info
fi
expect 0 "--require-gpu" -- --help
expect 0 "CSM_EGL_DEVICE" -- --help
exit $fail
