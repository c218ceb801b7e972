"""Every shell and Python block of README.md and the guide (docs/*.md) runs and succeeds.

A block runs as written in a scratch folder that links the repository's top folders (so that
`tests/data/...` and `examples/...` resolve and what a command writes stays in the scratch), with
two substitutions, both for the binary CI has built: `cargo run --release --` and
`target/release/rinshan` become the `rinshan` command under test. An HTML comment right before a
block changes how it runs, and says why:

    <!-- docs-test: skip REASON -->     not run (CI's own build, an install, hours of training)
    <!-- docs-test: smoke                run these lines instead: the block's short form
    COMMANDS -->
    <!-- docs-test: setup COMMAND -->   run COMMAND first (e.g. copy a log to the name used)
    <!-- docs-test: server [SETUP] -->  the block ends in a server, which must still be running
                                        after a few seconds (SETUP and the commands before it
                                        having succeeded)

A renamed flag or function then fails this test instead of misleading a reader.
"""

import os
import pathlib
import re
import signal
import subprocess
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
PAGES = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
LANGS = {"sh": "shell", "bash": "shell", "console": "shell", "python": "python"}
DIRECTIVE = re.compile(r"<!--\s*docs-test:\s*(\w+)\s*(.*?)\s*-->", re.S)
# A server block passes when it is still serving after this long.
SERVER_SECONDS = 8
TIMEOUT = 600


def blocks():
    """(page, line, language, code, directive, argument) for every shell and Python block."""
    out = []
    for page in PAGES:
        text = page.read_text()
        lines = text.split("\n")
        i = 0
        while i < len(lines):
            m = re.match(r"^```(\w+)\s*$", lines[i])
            if not m:
                i += 1
                continue
            end = next(j for j in range(i + 1, len(lines)) if lines[j].startswith("```"))
            lang = LANGS.get(m.group(1))
            if lang:
                # The directive is the comment that ends on the line before the fence.
                before = "\n".join(lines[:i]).rstrip()
                found = None
                if before.endswith("-->"):
                    start = before.rfind("<!--")
                    found = DIRECTIVE.fullmatch(before[start:])
                directive, arg = (found.group(1), found.group(2)) if found else ("run", "")
                code = "\n".join(lines[i + 1 : end])
                out.append((page.relative_to(REPO), i + 1, lang, code, directive, arg))
            i = end + 1
    return out


BLOCKS = blocks()


def substituted(code, cli):
    return code.replace("cargo run --release --", cli).replace("target/release/rinshan", cli)


@pytest.fixture
def scratch(tmp_path):
    for top in ("tests", "examples", "rules", "python", "runtime", "target"):
        (tmp_path / top).symlink_to(REPO / top)
    return tmp_path


def test_every_block_is_found():
    # The README's Python loop and the two commands are among them: the parser reads the pages.
    pages = {str(p) for p, *_ in BLOCKS}
    assert "README.md" in pages and len(BLOCKS) >= 20, BLOCKS
    for page, line, _, _, directive, arg in BLOCKS:
        assert directive in ("run", "skip", "smoke", "setup", "server"), (
            f"{page}:{line}: {directive}"
        )
        assert directive != "skip" or arg, f"{page}:{line}: a skip says why"


@pytest.mark.parametrize(
    "page,line,lang,code,directive,arg",
    BLOCKS,
    ids=[f"{p}:{n}" for p, n, *_ in BLOCKS],
)
def test_doc_block_runs(page, line, lang, code, directive, arg, cli, scratch):
    if directive == "skip":
        pytest.skip(arg)
    env = dict(os.environ)
    # The virtualenv's python (with rinshan, numpy, PyTorch) before any other.
    env["PATH"] = os.pathsep.join([str(pathlib.Path(sys.executable).parent), env.get("PATH", "")])
    if "RINSHAN_MJAI_PYTHON" in code + arg and not env.get("RINSHAN_MJAI_PYTHON"):
        pytest.skip("needs RINSHAN_MJAI_PYTHON (the mjai package's virtualenv, .ci/mjai-venv)")
    if directive == "smoke":
        code = arg
    if directive in ("setup", "server") and arg:
        code = arg + "\n" + code
    code = substituted(code, str(pathlib.Path(cli).resolve()))
    if lang == "shell":
        code = code.replace("\\\n", " ")  # one line per command, continuations joined
    where = f"{page}:{line}"
    if lang == "python":
        script = scratch / "block.py"
        script.write_text(code)
        cmd = [sys.executable, str(script)]
    else:
        cmd = ["bash", "-euo", "pipefail", "-c", code]
    if directive == "server":
        # Every command before the last must succeed; the last (the server) must keep running.
        head, _, last = code.rstrip().rpartition("\n")
        if head.strip():
            done = subprocess.run(
                ["bash", "-euo", "pipefail", "-c", head], cwd=scratch, env=env, timeout=TIMEOUT
            )
            assert done.returncode == 0, f"{where}: exit {done.returncode}"
        # A session of its own, so that the whole group (bash and the server) is stopped after.
        proc = subprocess.Popen(["bash", "-c", last], cwd=scratch, env=env, start_new_session=True)
        try:
            assert proc.wait(timeout=SERVER_SECONDS) is None, f"{where}: the server exited"
        except subprocess.TimeoutExpired:
            pass
        finally:
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:  # the server had exited: the assertion says so
                pass
            proc.wait()
        return
    done = subprocess.run(
        cmd, cwd=scratch, env=env, timeout=TIMEOUT, capture_output=True, text=True
    )
    assert done.returncode == 0, (
        f"{where} ({directive}) exited {done.returncode}:\n{code}\n"
        f"--- stdout\n{done.stdout[-3000:]}\n--- stderr\n{done.stderr[-3000:]}"
    )
