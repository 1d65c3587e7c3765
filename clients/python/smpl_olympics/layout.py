"""Where each named block of an observation lies, and each named field inside a block: the one
layout description the package reads observations by (the C++ side's is
clients/cpp/observation_layout.h). The server sends it with each match (block names and sizes,
then each block's fields, names and sizes), and the catalog holds the same for every mode, built
from what each sport declares where it writes its blocks; nothing here counts offsets by hand.

    layout = ObservationLayout.from_catalog(catalog.mode("soccer", "1v1"))
    layout.field(obs, "ball", "position")      # 3 floats
    layout.offset("ball", "position"), layout.size("ball", "position")
"""


class ObservationLayout:
    def __init__(self, blocks):
        """blocks: [(name, size, [(field, size), ...]), ...] in observation order; a block's fields,
        where it has any, tile it in order."""
        self.entries = [(name, size, [tuple(f) for f in fields]) for name, size, fields in blocks]
        self.blocks, self.fields = {}, {}  # name -> slice, (block, field) -> slice
        at = 0
        for name, size, fields in self.entries:
            self.blocks[name] = slice(at, at + size)
            field_at = at
            for field, field_size in fields:
                self.fields[(name, field)] = slice(field_at, field_at + field_size)
                field_at += field_size
            if fields and field_at != at + size:
                raise ValueError(f"observation block {name!r} holds {size} floats, its fields "
                                 f"{field_at - at}")
            at += size
        self.total = at

    @classmethod
    def from_catalog(cls, spec):
        """A mode's entry of the catalog (catalog.mode(...))."""
        return cls([(b["name"], b["size"], [(f["name"], f["size"]) for f in b.get("fields", [])])
                    for b in spec["observation"]])

    @classmethod
    def from_description(cls, description):
        """What the server sent when the match was created or joined (MatchClient's dict)."""
        fields = description.get("obs_fields") or [[] for _ in description["obs_blocks"]]
        return cls([(name, size, block_fields)
                    for (name, size), block_fields in zip(description["obs_blocks"], fields)])

    def _slice(self, block, field=None):
        if block not in self.blocks:
            raise KeyError(f"no observation block {block!r}; blocks: {', '.join(self.blocks)}")
        if field is None:
            return self.blocks[block]
        if (block, field) not in self.fields:
            known = ", ".join(f for b, f in self.fields if b == block)
            raise KeyError(f"observation block {block!r} has no field {field!r}; its fields: "
                           f"{known or 'none'}")
        return self.fields[(block, field)]

    def offset(self, block, field=None):
        """Where the block (or its field) starts in an observation."""
        return self._slice(block, field).start

    def size(self, block, field=None):
        s = self._slice(block, field)
        return s.stop - s.start

    def block(self, observation, name):
        return observation[self._slice(name)]

    def field(self, observation, block, name):
        return observation[self._slice(block, name)]
