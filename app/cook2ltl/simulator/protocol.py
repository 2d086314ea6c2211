"""The player's side of AI2-THOR's FIFO protocol (ai2thor/fifo_server.py).

A message is a run of fields, each a 5-byte header (field type: unsigned byte,
body length: unsigned 32-bit big-endian) and the body, closed by an
END_OF_MESSAGE header with an empty body. The Controller sends one ACTION field
holding the action as JSON; the player answers with one METADATA field holding
msgpack (image fields are optional, and this kitchen sends none).
"""

from __future__ import annotations

import json
import struct
from typing import Any, BinaryIO

import msgpack

HEADER = struct.Struct("!BI")

# Field types, numbered as in ai2thor.fifo_server.FieldType.
METADATA = 1
ACTION = 2
END_OF_MESSAGE = 255


class ProtocolError(Exception):
    """The Controller sent something that is not a well-formed message."""


def _read_exactly(stream: BinaryIO, size: int) -> bytes | None:
    data = stream.read(size)
    if not data:
        return None  # the Controller closed its end: a clean shutdown
    while len(data) < size:
        more = stream.read(size - len(data))
        if not more:
            raise ProtocolError(f"message cut short: wanted {size} bytes, got {len(data)}")
        data += more
    return data


def read_message(stream: BinaryIO) -> dict[int, bytes] | None:
    """The next message as {field type: body}, or None once the Controller has gone."""
    fields: dict[int, bytes] = {}
    while True:
        header = _read_exactly(stream, HEADER.size)
        if header is None:
            if fields:
                raise ProtocolError("message cut short before END_OF_MESSAGE")
            return None
        field_type, length = HEADER.unpack(header)
        if field_type == END_OF_MESSAGE:
            return fields
        body = _read_exactly(stream, length) if length else b""
        if body is None:
            raise ProtocolError("message cut short inside a field")
        fields[field_type] = body


def read_action(stream: BinaryIO) -> dict[str, Any] | None:
    message = read_message(stream)
    if message is None:
        return None
    if ACTION not in message:
        raise ProtocolError(f"expected an ACTION field, got field types {sorted(message)}")
    action = json.loads(message[ACTION])
    if not isinstance(action, dict):
        raise ProtocolError(f"an action must be a JSON object, got {type(action).__name__}")
    return action


def encode_fields(fields: list[tuple[int, bytes]]) -> bytes:
    parts = [HEADER.pack(kind, len(body)) + body for kind, body in fields]
    parts.append(HEADER.pack(END_OF_MESSAGE, 0))
    return b"".join(parts)


def write_metadata(stream: BinaryIO, metadata: dict[str, Any]) -> None:
    stream.write(encode_fields([(METADATA, msgpack.packb(metadata, use_bin_type=True))]))
    stream.flush()
