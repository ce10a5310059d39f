"""One glTF buffer, carried as a data URI, filled accessor by accessor: what the scene
generators beside this file share."""
import base64


class Buffer:
    def __init__(self):
        self.blob = b""
        self.views = []
        self.accessors = []

    def add(self, data, target, ctype, count, typ, extra=None):
        """Appends `data` (4-byte aligned) as a buffer view and an accessor; returns its index."""
        while len(self.blob) % 4:
            self.blob += b"\x00"
        self.views.append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data),
                           "target": target})
        self.blob += data
        acc = {"bufferView": len(self.views) - 1, "componentType": ctype, "count": count, "type": typ}
        acc.update(extra or {})
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def buffers(self):
        return [{"byteLength": len(self.blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(self.blob).decode()}]
