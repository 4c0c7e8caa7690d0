#!/usr/bin/env python3
"""Lays out the real-file gallery (tools/gltf_real_models.txt) in MODELS_DIR from git clones of its repositories,
each file as it was at the commit the list names, with a .gltf's external buffers and images beside it. Never run
it inside the repo: the models are not committed. Render them with
`tools/gltf_gallery.sh VKMC MODELS_DIR OUT --list tools/gltf_real_models.txt`.

  python3 tools/gltf_real_fetch.py CLONES_DIR MODELS_DIR [--list FILE]

CLONES_DIR holds one clone (bare or not) per repository, named owner__repo, e.g.
`git clone --bare https://github.com/pmndrs/examples CLONES_DIR/pmndrs__examples`; the script names every clone
it lacks. A file whose blob the clone lacks (a Git LFS pointer, a partial clone) is reported and skipped. --list
reads another list of the same form. Exits 1 where a clone or a file was missing.
"""
import json
import os
import posixpath
import struct
import subprocess
import sys
import urllib.parse

LIST = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gltf_real_models.txt")


def blob(git_dir, commit, path):
    """The file's bytes at the commit, or None where the clone lacks it."""
    done = subprocess.run(["git", "--git-dir", git_dir, "cat-file", "blob", f"{commit}:{path}"], capture_output=True)
    return done.stdout if done.returncode == 0 else None


def gltf_json(data):
    """The JSON object of a .gltf, or of a .glb's first chunk; {} where there is none to read (a Git LFS pointer, a
    truncated or malformed file: vkmc names what is wrong with it when it renders)."""
    try:
        if data[:4] == b"glTF":
            length = struct.unpack("<I", data[12:16])[0]
            data = data[20:20 + length]
        doc = json.loads(data)
    except (struct.error, ValueError):
        return {}
    return doc if isinstance(doc, dict) else {}


def external_uris(gltf_bytes):
    """A .gltf's or .glb's buffer and image files (relative URIs, decoded), not its data: URIs (a .glb may name
    images beside it, as Kenney's kits do)."""
    doc = gltf_json(gltf_bytes)
    entries = [e for key in ("buffers", "images") if isinstance(doc.get(key), list) for e in doc[key]]
    uris = [e.get("uri") for e in entries if isinstance(e, dict)]
    return [urllib.parse.unquote(u) for u in uris if isinstance(u, str) and u and not u.startswith("data:")]


def git_dir_of(clone):
    top = subprocess.run(["git", "-C", clone, "rev-parse", "--git-dir"], capture_output=True, text=True)
    if top.returncode != 0:
        return None
    d = top.stdout.strip()
    return d if os.path.isabs(d) else os.path.join(clone, d)


def main():
    args = sys.argv[1:]
    listed = LIST
    if len(args) == 4 and args[2] == "--list":
        listed = args[3]
    elif len(args) != 2:
        sys.exit(__doc__)
    clones, models = args[0], args[1]
    entries = []
    for line in open(listed):
        if line.strip() and not line.startswith("#"):
            name, path, source = [f.strip() for f in line.split(" | ")[:3]]
            repo, commit = source.split("@")
            entries.append((name, path, repo, commit))
    missing_clones = sorted({repo for _, _, repo, _ in entries
                             if git_dir_of(os.path.join(clones, repo.replace("/", "__"))) is None})
    for repo in missing_clones:
        print(f"gltf_real_fetch: no clone of {repo}: git clone --bare https://github.com/{repo} "
              f"{os.path.join(clones, repo.replace('/', '__'))}", file=sys.stderr)
    laid, absent = 0, 0
    for name, path, repo, commit in entries:
        if repo in missing_clones:
            continue
        git_dir = git_dir_of(os.path.join(clones, repo.replace("/", "__")))
        in_repo = path.split("/", 1)[1]
        wanted = [in_repo]
        data = blob(git_dir, commit, in_repo)
        if data is not None and in_repo.endswith((".gltf", ".glb")):
            wanted += [posixpath.normpath(posixpath.join(posixpath.dirname(in_repo), u)) for u in external_uris(data)]
        for file in wanted:
            content = data if file == in_repo else blob(git_dir, commit, file)
            if content is None:
                print(f"gltf_real_fetch: {name}: {repo}@{commit[:12]} has no {file} in this clone", file=sys.stderr)
                absent += 1
                continue
            out = os.path.join(models, path.split("/", 1)[0], file)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with open(out, "wb") as f:
                f.write(content)
        laid += 1
    print(f"gltf_real_fetch: {laid} of {len(entries)} files laid out in {models}; {absent} files absent; "
          f"{len(missing_clones)} repositories not cloned")
    sys.exit(1 if absent or missing_clones else 0)


if __name__ == "__main__":
    main()
