"""Changes one double of a host's sealed restart block (sbc/saved.h: marker, length, seal, checksum, values) in a
restart file, then seals it again (as a writer that computed a wrong value would) unless 'unsealed' follows, so
that the value reaches the block's own checks; without the seal again the checksum refuses it. Exits 1 when the
marker is not in the file.

    restart_edit.py FILE MARKER WHICH VALUE [unsealed]

WHICH: the value's offset from the marker, or an expression over v(k), the block's k-th value (v(1) is the
length, so 'v(1)' is the last value); VALUE a number, nan or inf."""
import struct
import sys

path, marker, which, value = sys.argv[1], float(sys.argv[2]), sys.argv[3], float(sys.argv[4])
data = bytearray(open(path, 'rb').read())
at = data.find(struct.pack('d', marker))
if at < 0:
    sys.exit(1)


def v(k):
    return struct.unpack_from('d', data, at + 8 * int(k))[0]


n = int(v(1))
k = int(eval(which, {'v': v}))
struct.pack_into('d', data, at + 8 * k, value)
if k >= 4 and sys.argv[5:] != ['unsealed']:   # the checksum of the values after the head (sbc_saved_seal)
    h = 0xcbf29ce484222325
    for b in data[at + 32: at + 8 * (n + 1)]:
        h = ((h ^ b) * 1099511628211) & 0xffffffffffffffff
    struct.pack_into('d', data, at + 24, float((h ^ (h >> 52)) & ((1 << 52) - 1)))
open(path, 'wb').write(data)
