#!/usr/bin/env python3
"""Export the real-world POV-Ray scenes listed in tests/wild/list.tsv.

usage: scripts/fetch-wild.py [--list FILE] [--filter SUBSTR] [--mirror DIR]

Each line of the list pins a scene to a repository and commit:

    repo<TAB>commit<TAB>scene path<TAB>extra paths<TAB>category<TAB>yes|no<TAB>note

For every distinct repository the script looks for a git directory in the mirror
(--mirror, else $DURER_WILD_MIRROR, else /work/.mirror; `owner+name`, as a bare
repository or with a `repo/` or `repo/.git` inside), else in conformance-work/wild-git/,
else clones https://github.com/owner/name there (bare). Repositories it cannot reach are
reported and skipped.

For every scene it then exports, with `git archive <commit> -- <paths> | tar -x`, the
scene's folder and its extra paths (comma-separated) into
conformance-work/wild/owner+name/, keeping the paths of the repository. A stamp file
there records which commit each path was exported from, so reruns only export what is
missing (one repository may pin several commits, for different paths).

--filter SUBSTR keeps the lines whose repository or scene path contains SUBSTR.
The scene files are not committed to durer; only the pinned references are.
Exits non-zero only if no scene at all could be prepared. Standard library only.
"""

import argparse
import os
import posixpath
import shutil
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_LIST = os.path.join(REPO, "tests", "wild", "list.tsv")
WORK = os.path.join(REPO, "conformance-work")
TREES = os.path.join(WORK, "wild")
CLONES = os.path.join(WORK, "wild-git")
DEFAULT_MIRROR = os.environ.get("DURER_WILD_MIRROR", "/work/.mirror")
STAMP = ".fetch-wild-stamp"
CLONE_TIMEOUT = 600


class Scene:
    """One line of the list: a scene file pinned to a repository commit."""

    def __init__(self, repo, commit, path, extra_paths):
        self.repo = repo
        self.commit = commit
        self.path = path
        self.extra_paths = extra_paths

    @property
    def export_paths(self):
        """Repository paths to export: the scene's folder and the extra paths."""
        folder = posixpath.dirname(self.path) or "."
        return [folder] + self.extra_paths


def read_list(path, substring):
    """The scenes of the list whose repository or scene path contains the substring."""
    scenes = []
    with open(path, encoding="utf-8") as handle:
        for number, line in enumerate(handle, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            fields = [field.strip() for field in line.split("\t")]
            if len(fields) < 4:
                raise SystemExit(f"{path}:{number}: expected repo, commit, scene path, "
                                 "extra paths, ...")
            repo, commit, scene_path, extra = fields[:4]
            if substring and substring not in repo and substring not in scene_path:
                continue
            extra_paths = [] if extra in ("", "-") else [
                item.strip().rstrip("/") for item in extra.split(",") if item.strip()]
            scenes.append(Scene(repo, commit, scene_path, extra_paths))
    return scenes


def git(git_dir, *arguments, stdin_data=None, **options):
    """Run a git command on a git directory; returns the CompletedProcess."""
    return subprocess.run(["git", "--git-dir", git_dir, *arguments], input=stdin_data,
                          stdin=None if stdin_data is not None else subprocess.DEVNULL,
                          capture_output=True, **options)


def has_commit(git_dir, commit):
    if not os.path.isdir(git_dir):
        return False
    return git(git_dir, "cat-file", "-e", f"{commit}^{{commit}}").returncode == 0


def find_git_dir(repo, commit, mirror):
    """A git directory holding the commit, cloning it if need be; None if unavailable."""
    name = repo.replace("/", "+")
    candidates = [os.path.join(mirror, name, *tail)
                  for tail in ([], ["repo"], ["repo", ".git"], [".git"])]
    clone = os.path.join(CLONES, name)
    for candidate in candidates + [clone]:
        if has_commit(candidate, commit):
            return candidate
    if os.path.isdir(clone):
        git(clone, "fetch", "--quiet", "origin", commit, timeout=CLONE_TIMEOUT)
    else:
        os.makedirs(CLONES, exist_ok=True)
        try:
            subprocess.run(["git", "clone", "--bare", "--quiet",
                            f"https://github.com/{repo}", clone],
                           stdin=subprocess.DEVNULL, capture_output=True,
                           timeout=CLONE_TIMEOUT,
                           env=dict(os.environ, GIT_TERMINAL_PROMPT="0"))
        except subprocess.TimeoutExpired:
            pass
    return clone if has_commit(clone, commit) else None


def read_stamp(tree):
    """{repository path: commit} of what was already exported into the tree."""
    try:
        with open(os.path.join(tree, STAMP), encoding="utf-8") as handle:
            pairs = [line.split("\t", 1) for line in handle.read().splitlines()
                     if "\t" in line]
    except FileNotFoundError:
        return {}
    return {path: commit for commit, path in pairs}


def write_stamp(tree, exported):
    with open(os.path.join(tree, STAMP), "w", encoding="utf-8") as handle:
        for path in sorted(exported):
            handle.write(f"{exported[path]}\t{path}\n")


def remove_path(tree, path):
    """Remove an earlier export of a repository path (from another commit)."""
    target = os.path.join(tree, path)
    if os.path.isdir(target) and path != ".":
        shutil.rmtree(target)
    elif os.path.isfile(target):
        os.remove(target)


def archive_into(git_dir, commit, paths, tree):
    """`git archive <commit> -- <paths> | tar -x -C <tree>`; returns an error message or None."""
    archive = subprocess.Popen(["git", "--git-dir", git_dir, "archive", "--format=tar",
                                commit, "--", *paths],
                               stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE)
    untar = subprocess.run(["tar", "-x", "-C", tree], stdin=archive.stdout,
                           capture_output=True)
    archive.stdout.close()
    archive_error = archive.stderr.read().decode("utf-8", "replace").strip()
    archive.wait()
    if archive.returncode != 0:
        return archive_error or f"git archive exited with {archive.returncode}"
    if untar.returncode != 0:
        return untar.stderr.decode("utf-8", "replace").strip() or "tar failed"
    return None


def present_files(git_dir, commit, paths):
    """The files under the paths whose content the git directory holds, and the others.

    Mirrors may lack large blobs; the scenes rarely need them.
    """
    listing = git(git_dir, "ls-tree", "-r", "-z", commit, "--", *paths).stdout
    entries = [entry.decode("utf-8", "surrogateescape")
               for entry in listing.split(b"\0") if entry]
    blobs = {}
    for entry in entries:
        meta, path = entry.split("\t", 1)
        kind, object_id = meta.split()[1:3]
        if kind == "blob":
            blobs[path] = object_id
    check = git(git_dir, "cat-file", "--batch-check",
                stdin_data="\n".join(blobs.values()).encode())
    missing_ids = {line.split()[0] for line in check.stdout.decode().splitlines()
                   if line.endswith(" missing")}
    present = [path for path, object_id in blobs.items() if object_id not in missing_ids]
    missing = [path for path, object_id in blobs.items() if object_id in missing_ids]
    return present, missing


def export(git_dir, commit, paths, tree):
    """Extract the paths of the commit into the tree; returns an error message or None."""
    if archive_into(git_dir, commit, paths, tree) is None:
        return None
    present, missing = present_files(git_dir, commit, paths)
    if not present:
        return "nothing to export (paths missing from the commit or the mirror)"
    for path in missing:
        print(f"  skipped (not in the mirror): {path}", file=sys.stderr)
    # Literal pathspecs, in batches to stay below the command-line limit.
    for start in range(0, len(present), 500):
        batch = [f":(literal){path}" for path in present[start:start + 500]]
        error = archive_into(git_dir, commit, batch, tree)
        if error:
            return error
    return None


def prepare_repo(repo, commit, scenes, git_dir):
    """Export every scene of one repository at one commit; returns the number ready."""
    tree = os.path.join(TREES, repo.replace("/", "+"))
    os.makedirs(tree, exist_ok=True)
    exported = read_stamp(tree)
    ready = 0
    for scene in scenes:
        missing = [path for path in scene.export_paths if exported.get(path) != commit]
        if missing:
            for path in missing:
                if path in exported:
                    remove_path(tree, path)
            error = export(git_dir, commit, missing, tree)
            if error:
                print(f"  {repo}: {scene.path}: {error}", file=sys.stderr)
                continue
            exported.update((path, commit) for path in missing)
            write_stamp(tree, exported)
        if os.path.isfile(os.path.join(tree, scene.path)):
            ready += 1
        else:
            print(f"  {repo}: {scene.path}: not in the exported tree", file=sys.stderr)
    return ready


def main():
    parser = argparse.ArgumentParser(
        description="Export the real-world POV-Ray scenes of tests/wild/list.tsv.")
    parser.add_argument("--list", default=DEFAULT_LIST, help="scene list (tsv)")
    parser.add_argument("--filter", default="",
                        help="only lines whose repository or scene path contains this")
    parser.add_argument("--mirror", default=DEFAULT_MIRROR,
                        help="folder of owner+name git directories")
    options = parser.parse_args()

    by_repo = {}
    for scene in read_list(options.list, options.filter):
        by_repo.setdefault((scene.repo, scene.commit), []).append(scene)

    found, unavailable, ready, total = set(), [], 0, 0
    for (repo, commit), scenes in by_repo.items():
        total += len(scenes)
        git_dir = find_git_dir(repo, commit, options.mirror)
        if git_dir is None:
            unavailable.append(f"{repo}@{commit[:12]}")
            print(f"  {repo}: unavailable (no mirror, clone failed)", file=sys.stderr)
            continue
        found.add(repo)
        ready += prepare_repo(repo, commit, scenes, git_dir)

    print(f"repositories: {len(found)} found, {len(unavailable)} unavailable")
    for name in unavailable:
        print(f"  unavailable: {name}")
    print(f"scenes ready: {ready} of {total} in {os.path.relpath(TREES, REPO)}/")
    return 0 if ready else 1


if __name__ == "__main__":
    sys.exit(main())
