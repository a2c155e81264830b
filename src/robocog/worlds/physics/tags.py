"""AprilTag tag36h11 images made by robocog from the family's published codes.

A tag36h11 marker is a 10 x 10 grid of cells: a white ring, a black ring, and 6 x 6 data
cells inside. Each of the family's codes is a 36-bit number; bit ``i`` (counted from the
most significant) is drawn white at the data cell ``LAYOUT[i]``. The codes below are the
first entries of the published family (ids 0-31): the detector decodes a marker back to
its id by the same table, so a texture drawn here is read as the id it was made for.

The PNG is written by hand (zlib and a CRC per chunk) so no imaging library is needed.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np

#: tag36h11 ids 0-31 (the family has 587; the tabletop needs fewer than 32)
CODES: tuple[int, ...] = (
    0xD7E00984B, 0xDDA664CA7, 0xDC4A1C821, 0xE17B470E9, 0xEF91D01B1, 0xF429CDD73,
    0x05DA29225, 0x1106CBA43, 0x223BED79D, 0x21F51213C, 0x33EB19CA6, 0x3F76EB0F8,
    0x469A97414, 0x45DCFE0B0, 0x4A6465F72, 0x51801DB96, 0x5EB946B4E, 0x68A7CC2EC,
    0x6F0BA2652, 0x78765559D, 0x87B83D129, 0x86CC4A5C5, 0x8B64DF90F, 0x9C577B611,
    0xA3810F2F5, 0xAF4D75B83, 0xB59A03FEF, 0xBB1096F85, 0xD1B92FC76, 0xD0DD509D2,
    0xE2CFDA160, 0x2FF497C63,
)  # fmt: skip

#: (x, y) of each code bit inside the black ring (1..6 each way), most significant first:
#: the family draws its bits as four rotated copies of one nine-cell quarter
_QUARTER = ((1, 1), (2, 1), (3, 1), (4, 1), (5, 1), (2, 2), (3, 2), (4, 2), (3, 3))


def _rotate(x: int, y: int, turns: int) -> tuple[int, int]:
    for _ in range(turns):
        x, y = 7 - y, x
    return x, y


LAYOUT: tuple[tuple[int, int], ...] = tuple(
    _rotate(x, y, turns) for turns in range(4) for x, y in _QUARTER
)

#: cells across a whole marker, and across its black square (what a detector calls its size)
TOTAL_CELLS = 10
BLACK_CELLS = 8


def tag_cells(tag_id: int) -> np.ndarray:
    """The 10 x 10 cells of tag ``tag_id`` (1 white, 0 black), row 0 at the top."""
    if not 0 <= tag_id < len(CODES):
        raise ValueError(f"tag36h11 id {tag_id} is not among the {len(CODES)} known here")
    cells = np.ones((TOTAL_CELLS, TOTAL_CELLS), dtype=np.uint8)
    cells[1:9, 1:9] = 0
    code = CODES[tag_id]
    for i, (x, y) in enumerate(LAYOUT):
        if code >> (35 - i) & 1:
            cells[y + 1, x + 1] = 1
    return cells


def tag_image(tag_id: int, cell_pixels: int = 8) -> np.ndarray:
    """The tag as a grey image (0 or 255), ``cell_pixels`` pixels per cell."""
    cells = tag_cells(tag_id) * 255
    return np.kron(cells, np.ones((cell_pixels, cell_pixels), dtype=np.uint8)).astype(np.uint8)


def png_bytes(image: np.ndarray) -> bytes:
    """Encode a grey (H, W) or RGB (H, W, 3) uint8 image as PNG."""
    img = np.ascontiguousarray(image, dtype=np.uint8)
    if img.ndim == 2:
        colour = 0
    elif img.ndim == 3 and img.shape[2] == 3:
        colour = 2
    else:
        raise ValueError("a PNG here is grey (H, W) or RGB (H, W, 3)")
    height, width = img.shape[:2]
    rows = b"".join(b"\x00" + img[r].tobytes() for r in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(rows, 6))
        + chunk(b"IEND", b"")
    )
