"""cagd_ref: the reference implementation of the CAGD course (after T. W. Sederberg's notes).

One module per topic of the notes: `geometry` (ch. 1), `bezier` (ch. 2),
`polynomials` (ch. 2-3), `continuity` (§2.10-2.11); `plotting` and `widgets`
draw them, `grading` grades students' versions, `course` reads `book.toml`.
"""

__version__ = "0.1.0"
