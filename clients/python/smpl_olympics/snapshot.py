"""Export a policy MLP as an olympics snapshot (docs/snapshots.md) for olympics-agent and the league.

    from smpl_olympics.snapshot import export_mlp
    export_mlp(actor, "policy-v7.safetensors", policy_id="mine", policy_version="7")  # torch
    export_mlp([(w0, b0), (w1, b1)], "policy.safetensors", activation="relu")         # numpy

The file is plain safetensors (no extra package needed to write or read it): float32 tensors
layers.<i>.weight [out, in] and layers.<i>.bias [out], optional obs_mean / obs_std, and metadata
format=olympics-mlp, activation, output, obs_size, action_size plus any keywords you pass.
"""
import json
import os
import struct

import numpy as np

ACTIVATIONS = ("silu", "relu", "tanh", "elu")


def _layers_and_activation(model, activation):
    if isinstance(model, (list, tuple)):
        return [(np.asarray(w, np.float32), np.asarray(b, np.float32)) for w, b in model], activation
    import torch  # a PyTorch module: its Linear layers in order, its activation if it has one

    layers, found = [], None
    for module in model.modules():
        if isinstance(module, torch.nn.Linear):
            layers.append((module.weight.detach().cpu().numpy().astype(np.float32),
                           module.bias.detach().cpu().numpy().astype(np.float32)))
        for name, cls in (("silu", torch.nn.SiLU), ("relu", torch.nn.ReLU), ("tanh", torch.nn.Tanh),
                          ("elu", torch.nn.ELU)):
            if isinstance(module, cls):
                found = found or name
    return layers, activation or found or "silu"


def export_mlp(model, path, activation=None, output="none", obs_mean=None, obs_std=None, **metadata):
    layers, activation = _layers_and_activation(model, activation)
    activation = activation or "silu"
    if activation not in ACTIVATIONS:
        raise ValueError(f"activation {activation!r} is not one of {ACTIVATIONS}")
    if output not in ("none", "tanh"):
        raise ValueError("output must be 'none' or 'tanh'")
    if not layers:
        raise ValueError("no Linear layers to export")
    for i, (w, b) in enumerate(layers):
        if w.ndim != 2 or b.shape != (w.shape[0],):
            raise ValueError(f"layer {i}: weight must be [out, in] and bias [out]")
        if i and w.shape[1] != layers[i - 1][0].shape[0]:
            raise ValueError(f"layer {i} takes {w.shape[1]} inputs, layer {i - 1} gives {layers[i - 1][0].shape[0]}")
    tensors = {}
    for i, (w, b) in enumerate(layers):
        tensors[f"layers.{i}.weight"], tensors[f"layers.{i}.bias"] = w, b
    if obs_mean is not None:
        tensors["obs_mean"] = np.asarray(obs_mean, np.float32)
        tensors["obs_std"] = np.asarray(obs_std, np.float32)
    meta = {"format": "olympics-mlp", "activation": activation, "output": output,
            "obs_size": str(layers[0][0].shape[1]), "action_size": str(layers[-1][0].shape[0])}
    meta.update({k: str(v) for k, v in metadata.items()})

    header, blobs, offset = {"__metadata__": meta}, [], 0
    for name, array in tensors.items():
        data = np.ascontiguousarray(array, dtype="<f4").tobytes()
        header[name] = {"dtype": "F32", "shape": list(array.shape), "data_offsets": [offset, offset + len(data)]}
        blobs.append(data)
        offset += len(data)
    text = json.dumps(header).encode()
    text += b" " * (-len(text) % 8)  # safetensors aligns the data
    # Written beside and renamed into place: a league watching the folder registers a snapshot
    # as soon as its name appears, and must never load a half-written file.
    partial = f"{path}.partial"
    with open(partial, "wb") as f:
        f.write(struct.pack("<Q", len(text)))
        f.write(text)
        for blob in blobs:
            f.write(blob)
    os.replace(partial, path)
    return path
