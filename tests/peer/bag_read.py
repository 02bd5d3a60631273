"""Read a rosbag2 directory (or a bare .mcap) with an independent reader and
print what it holds as one JSON object (the Rust tests make the assertions).

    python bag_read.py PATH [--reader rosbags|mcap] [--full TOPIC ...]

--reader rosbags (default): the `rosbags` package, with an EMPTY type store,
    so every type — the standard ones included — is rebuilt from the
    definitions stored in the bag (what `ros2 bag play` and Foxglove rely on);
    also reports metadata.yaml and the QoS profiles rosbags parsed.
--reader mcap: the `mcap` package with `mcap-ros2-support`'s decoder, on
    the bag's .mcap file (a second, unrelated CDR and .msg implementation).

Per topic: type, count, and for every message its log time, header stamp
(or /clock time), and `step` where the message has one; the whole decoded
message for the topics named with --full (and the first and last message
of every topic). A message that fails to decode is counted, never skipped
silently.
"""

import argparse
import json
import math
import sys
from pathlib import Path


def plain(x):
    """Decoded message -> JSON-able (dataclasses, slotted classes, numpy arrays, bytes)."""
    if x is None or isinstance(x, (bool, int, str)):
        return x
    if isinstance(x, float):
        return x if math.isfinite(x) else repr(x)
    if isinstance(x, (bytes, bytearray, memoryview)):
        return list(bytes(x))
    if hasattr(x, "tolist"):  # numpy arrays and scalars
        return plain(x.tolist())
    if isinstance(x, (list, tuple)):
        return [plain(v) for v in x]
    if isinstance(x, dict):
        return {k: plain(v) for k, v in x.items()}
    fields = getattr(x, "__dataclass_fields__", None)
    if fields is not None:
        return {k: plain(getattr(x, k)) for k, f in fields.items() if not k.startswith("__") and f._field_type.__class__.__name__ != "_FIELD_CLASSVAR" and k.upper() != k}
    slots = getattr(x, "__slots__", None)
    if slots:
        return {k: plain(getattr(x, k)) for k in slots if not k.startswith("_")}
    raise TypeError(f"cannot convert {type(x)}")


def stamp_of(m):
    """Header stamp (or /clock's time) in ns, if the message has one."""
    t = None
    if hasattr(m, "header"):
        t = m.header.stamp
    elif hasattr(m, "clock"):
        t = m.clock
    elif hasattr(m, "transforms") and len(m.transforms) > 0:
        t = m.transforms[0].header.stamp
    return None if t is None else int(t.sec) * 1_000_000_000 + int(t.nanosec)


class Collector:
    def __init__(self, full):
        self.full = set(full)
        self.topics = {}
        self.undecodable = []

    def add(self, topic, msgtype, log_time, decode):
        t = self.topics.setdefault(topic, {"type": msgtype, "count": 0, "log_times": [], "stamps": [], "steps": [],
                                          "messages": [], "first": None, "last": None})
        t["count"] += 1
        t["log_times"].append(int(log_time))
        try:
            m = decode()
        except Exception as e:  # noqa: BLE001 - counted and reported
            self.undecodable.append({"topic": topic, "log_time": int(log_time), "error": repr(e)})
            return
        t["stamps"].append(stamp_of(m))
        if hasattr(m, "step"):
            t["steps"].append(int(m.step))
        d = None
        if topic in self.full or t["first"] is None:
            d = plain(m)
            if topic in self.full:
                t["messages"].append(d)
            if t["first"] is None:
                t["first"] = d
        t["last_raw"] = m

    def finish(self):
        for t in self.topics.values():
            m = t.pop("last_raw", None)
            t["last"] = plain(m) if m is not None else None
        return {"topics": self.topics, "undecodable": self.undecodable}


def read_rosbags(path, full):
    from rosbags.highlevel import AnyReader
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    out = {"reader": "rosbags"}
    p = Path(path)
    if p.is_dir():
        from ruamel.yaml import YAML
        out["metadata_yaml"] = plain(YAML(typ="safe").load((p / "metadata.yaml").read_text()))
        with Reader(p) as r:
            out["rosbags_metadata"] = {"duration": r.duration, "start_time": r.start_time, "end_time": r.end_time,
                                       "message_count": r.message_count, "storage": type(r.storage).__name__ if hasattr(r, "storage") else None}
            out["connections"] = [
                {"topic": c.topic, "msgtype": c.msgtype, "msgcount": c.msgcount,
                 "serialization_format": c.ext.serialization_format,
                 "qos": [q._asdict() | {k: v.name.lower() for k, v in q._asdict().items() if hasattr(v, "name")}
                         | {k: list(v) for k, v in q._asdict().items() if isinstance(v, tuple)}
                         for q in c.ext.offered_qos_profiles],
                 "msgdef_format": c.msgdef.format.name}
                for c in r.connections
            ]
    col = Collector(full)
    with AnyReader([p], default_typestore=get_typestore(Stores.EMPTY)) as r:
        for c, t, raw in r.messages():
            col.add(c.topic, c.msgtype, t, lambda: r.deserialize(raw, c.msgtype))
    out.update(col.finish())
    return out


def read_mcap(path, full):
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    p = Path(path)
    if p.is_dir():
        p = sorted(p.glob("*.mcap"))[0]
    out = {"reader": "mcap"}
    col = Collector(full)
    factory = DecoderFactory()
    decoders = {}
    with open(p, "rb") as f:
        r = make_reader(f)
        h = r.get_header()
        out["header"] = {"profile": h.profile, "library": h.library}
        s = r.get_summary()
        out["schemas"] = {str(k): {"name": v.name, "encoding": v.encoding, "data": v.data.decode()} for k, v in s.schemas.items()}
        out["channels"] = {v.topic: {"message_encoding": v.message_encoding, "schema": s.schemas[v.schema_id].name,
                                     "metadata": dict(v.metadata)} for v in s.channels.values()}
        out["metadata_records"] = [{"name": m.name, "keys": sorted(m.metadata)} for m in r.iter_metadata()]
        for schema, channel, message in r.iter_messages():
            key = channel.id
            if key not in decoders:
                decoders[key] = factory.decoder_for(channel.message_encoding, schema)
            dec = decoders[key]
            col.add(channel.topic, schema.name, message.log_time, lambda: dec(message.data))
    out.update(col.finish())
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("path")
    ap.add_argument("--reader", choices=["rosbags", "mcap"], default="rosbags")
    ap.add_argument("--full", nargs="*", default=[])
    a = ap.parse_args()
    out = read_rosbags(a.path, a.full) if a.reader == "rosbags" else read_mcap(a.path, a.full)
    sys.stdout.write(json.dumps(out) + "\n")


if __name__ == "__main__":
    main()
