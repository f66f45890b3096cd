#!/usr/bin/env python3
"""Disassemble the kernels NVIDIA's Vulkan driver compiled, from its shader disk cache.

NVIDIA's driver keeps every compiled pipeline in the cache named by
__GL_SHADER_DISK_CACHE_PATH (with __GL_SHADER_DISK_CACHE=1 and
__GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1): `GLCache/<hash>/<hash>/<hash>.bin`. Seen with driver
580.159.04 (session 12): that file is a sequence of zstd frames; each kernel's frame holds an
"NVDA NVVM NVuc" container whose section table (at byte 0x28, entries of 32 bytes: type,
size, offset, ...) has one section of type 1, the machine code, at offset + 8. `nvdisasm -b
SM90` disassembles it; the container itself (from its "NVuc") gives the register count.

Usage: sass.py CACHE.bin OUT_PREFIX  ->  OUT_PREFIX-NN.sass, one per kernel, and a summary
(registers, loads, instructions) on stdout. Needs the Python module `zstandard` and
`nvdisasm` (CUDA's, or the one in Triton's wheel: triton/backends/nvidia/bin/nvdisasm; set
NVDISASM to its path). scripts/device/pending-h200.sh's parts copy such cache files to $OUT
(e.g. part trav12); run this here on what comes back.
"""
import os
import shutil
import struct
import subprocess
import sys

MAGIC = b"\x28\xb5\x2f\xfd"  # zstd frame
CONTAINER = b"NVDANVVMNVuc"


def frames(data):
    import zstandard

    dctx = zstandard.ZstdDecompressor()
    at = data.find(MAGIC)
    while at >= 0:
        try:
            out = dctx.decompressobj().decompress(data[at:])
        except zstandard.ZstdError:
            out = b""
        if out.startswith(CONTAINER):
            yield out
        at = data.find(MAGIC, at + 1)


def code_section(container):
    for entry in range(0x28, min(len(container) - 12, 0x800), 4):
        kind, size, offset = struct.unpack_from("<III", container, entry)
        if kind == 1 and 0x100 < size and offset + 8 + size <= len(container):
            return container[offset + 8:offset + 8 + size]
    return None


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    nvdisasm = os.environ.get("NVDISASM") or shutil.which("nvdisasm")
    if not nvdisasm:
        sys.exit("sass.py: no nvdisasm on PATH; set NVDISASM (see the docstring)")
    src, prefix = sys.argv[1], sys.argv[2]
    data = open(src, "rb").read()
    n = 0
    for container in frames(data):
        code = code_section(container)
        if code is None:
            continue
        tmp = f"{prefix}-{n:02}.bin"
        open(tmp, "wb").write(code)
        sass = subprocess.run([nvdisasm, "-b", "SM90", tmp], capture_output=True, text=True).stdout
        open(tmp, "wb").write(container[8:])
        info = subprocess.run([nvdisasm, "-b", "SM90", tmp], capture_output=True, text=True)
        os.remove(tmp)
        regs = next((l.split("=")[1] for l in (info.stdout + info.stderr).splitlines() if "Register count" in l), "?")
        out = f"{prefix}-{n:02}.sass"
        open(out, "w").write(sass)
        instructions = sum(1 for l in sass.splitlines() if l.strip().startswith("/*") and "NOP" not in l)
        print(f"{out}: {regs} registers, {instructions} instructions, {sass.count('LDG')} LDG, "
              f"{sass.count('LDL') + sass.count('STL')} local, {sass.count('I2F')} I2F")
        n += 1
    if n == 0:
        sys.exit(f"sass.py: no kernel found in {src} (a driver other than 580's may store it otherwise)")


main()
