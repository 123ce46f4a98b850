"""The CLI reference from the CLI itself: ``.. cli-help::`` runs the `stickiness` binary.

The binary is ``$STICKINESS_CLI`` (default ``target/debug/stickiness``; ``cargo xtask docs``
builds it). The directive emits the top-level ``--help`` and one section per subcommand (read
from the "Commands:" list of that help, so a new subcommand appears by itself) with its
``--help``, labelled ``cli-stickiness`` and ``cli-<subcommand>``. It also checks the hand-written overview ``cli.md``: every subcommand and every flag
of the help must be named there, and every flag named there must exist, so the overview cannot
drift from the binary either (a mismatch is a warning, an error under ``-W``).
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

from docutils import nodes
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

ROOT = Path(__file__).resolve().parents[3]
LOG = logging.getLogger(__name__)
FLAG = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*")


def _binary() -> str:
    return os.environ.get("STICKINESS_CLI", str(ROOT / "target" / "debug" / "stickiness"))


def _help(*args: str) -> str:
    out = subprocess.run(
        [_binary(), *args, "--help"], capture_output=True, text=True, check=True
    )
    return out.stdout.rstrip() + "\n"


def _commands(top: str) -> list[tuple[str, str]]:
    """(name, one-line description) of every subcommand listed by the top-level help."""
    block = top.split("Commands:", 1)[1].split("\n\n", 1)[0]
    found = []
    for line in block.splitlines():
        m = re.match(r"\s+([a-z][a-z0-9-]*)\s+(.*)", line)
        if m and m.group(1) != "help":
            found.append((m.group(1), m.group(2).strip()))
    return found


def _section(doc, title: str, ident: str, text: str, intro: str = "") -> nodes.section:
    sec = nodes.section(ids=[ident], names=[ident])
    sec += nodes.title(text=title)
    if intro:
        sec += nodes.paragraph(text=intro)
    block = nodes.literal_block(text, text)
    block["language"] = "text"
    sec += block
    doc.note_explicit_target(sec)  # a label: {ref}`cli-v-stick` links here
    return sec


class CliHelp(SphinxDirective):
    """Every subcommand's ``--help``, one section each."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        try:
            top = _help()
            commands = _commands(top)
            helps = {name: _help(name) for name, _ in commands}
        except (OSError, subprocess.CalledProcessError, IndexError) as e:
            LOG.warning("cannot run `%s --help`: %s (build it: cargo build -p cli)", _binary(), e,
                        location=self.get_location())
            return []
        doc = self.state.document
        out = [_section(doc, "stickiness", "cli-stickiness", top)]
        for name, desc in commands:
            out.append(_section(doc, f"stickiness {name}", f"cli-{name}", helps[name], desc))
        self._check_overview(top, helps)
        return out

    def _check_overview(self, top: str, helps: dict[str, str]) -> None:
        overview_path = Path(self.env.srcdir) / "cli.md"
        self.env.note_dependency(str(overview_path))
        overview = overview_path.read_text(encoding="utf-8")
        flags = set(FLAG.findall(top))
        for name, text in helps.items():
            if f"stickiness {name}" not in overview:
                LOG.warning("cli.md does not describe the subcommand `%s`", name,
                            location=self.get_location())
            flags.update(FLAG.findall(text))
        # flags of the `stickiness` commands only (not of `cargo install --path ...`)
        named = set(FLAG.findall("\n".join(
            line for line in overview.splitlines() if "cargo " not in line)))
        for flag in sorted(flags - named):
            LOG.warning("cli.md does not name the flag %s of the CLI", flag,
                        location=self.get_location())
        for flag in sorted(named - flags):
            LOG.warning("cli.md names %s, which no subcommand of the CLI takes", flag,
                        location=self.get_location())


def setup(app):
    app.add_directive("cli-help", CliHelp)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
