"""What went wrong, by kind: the disagreements of a compare record sorted into findings.

A *finding* is one kind of mistake by one side in one pair, with a count: OCCT's eight
"second, misplaced copy" rows at one crossing are one finding ``duplicate copies ×8``,
not eight disagreements.
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field
from typing import Any

__all__ = ["KINDS", "Finding", "fault_kind", "findings", "tally"]

KINDS = (
    "missed",
    "spurious",
    "duplicate copies",
    "misplaced",
    "tangency as a segment",
    "overlap in pieces",
    "both wrong",
)
"""The kinds of mistake, in the order the report lists them."""


def fault_kind(d: dict[str, Any]) -> str:
    """The kind of mistake a disagreement record shows, made by the side the arbiter ruled against.

    >>> fault_kind({"claimant": "relief_cad", "winner": "relief_cad", "claim": {"type": "point"},
    ...             "counter": [], "reason": "occt missed a true crossing point"})
    'missed'
    >>> fault_kind({"claimant": "occt", "winner": "relief_cad", "claim": {"type": "point"},
    ...             "counter": [], "reason": "occt reports a second, misplaced copy of a crossing point"})
    'duplicate copies'
    """
    claim, reason, winner = d.get("claim", {}), str(d.get("reason", "")), d.get("winner")
    if winner not in ("relief_cad", "occt"):
        return "both wrong"
    if winner == d.get("claimant"):  # the claim holds: the other side did not report it (whole)
        pieces = claim.get("type") == "overlap" and (d.get("counter") or "only part" in reason)
        return "overlap in pieces" if pieces else "missed"
    if claim.get("type") == "overlap":
        return "tangency as a segment" if d.get("truth") == "tangent" else "spurious"
    if "copy" in reason or "twice" in reason:
        return "duplicate copies"
    if "spurious" in reason or d.get("truth") == "nothing":
        return "spurious"
    return "misplaced"


def loser(d: dict[str, Any]) -> str:
    """The side that got it wrong: ``"occt"``, ``"relief_cad"`` or ``"both"``.

    >>> loser({"winner": "relief_cad"})
    'occt'
    """
    w = d.get("winner")
    return "occt" if w == "relief_cad" else "relief_cad" if w == "occt" else "both"


@dataclass
class Finding:
    """One kind of mistake by one side in one pair: ``count`` disagreements, the first as example."""

    side: str
    kind: str
    count: int
    example: dict[str, Any]
    reasons: list[str] = field(default_factory=list)


def _template(reason: str) -> str:
    return re.sub(r"[-+]?\d[\d.eE+-]*", "#", reason)


def findings(rec: dict[str, Any]) -> list[Finding]:
    """The record's disagreements grouped by (wrong side, kind, reason pattern), in order."""
    groups: dict[tuple[str, str, str], Finding] = {}
    for d in rec.get("disagreements", []):
        key = (loser(d), fault_kind(d), _template(str(d.get("reason", ""))))
        if key in groups:
            groups[key].count += 1
        else:
            groups[key] = Finding(key[0], key[1], 1, d, [str(d.get("reason", ""))])
    return list(groups.values())


def tally(recs: list[dict[str, Any]], side: str) -> dict[str, tuple[int, int, int]]:
    """Per kind, for one wrong side: ``(findings, pairs, disagreement rows)`` over the records."""
    found: Counter[str] = Counter()
    rows: Counter[str] = Counter()
    pairs: dict[str, set[str]] = {}
    for r in recs:
        for f in findings(r):
            if f.side == side or (f.side == "both" and side == "both"):
                found[f.kind] += 1
                rows[f.kind] += f.count
                pairs.setdefault(f.kind, set()).add(str(r.get("id")))
    return {k: (found[k], len(pairs[k]), rows[k]) for k in KINDS if found[k]}
