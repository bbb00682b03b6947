"""The light crossing parts (issue 36, point 4; docs/petsc.md, "Block Jacobi by part"):
`K = K_bd + K_off`, `K_bd` the diagonal blocks by part (part_blocks.py) and `K_off` the
links from a source in another part than the receiving leaf's. For a field `x`,
`‖K_off x‖₂ / ‖K x‖₂`, and `Σ K_off x / Σ K x`, the share of the light gathered by the
leaves that comes from other parts (`K ≥ 0`, `x ≥ 0`): what GMRES must carry between the
blocks that block Jacobi solves.
"""


def crossing(K, blocks, offset, cells, x):
    """`(‖K_off x‖₂/‖K x‖₂, Σ K_off x/Σ K x)` with the local `blocks` (this rank's leaves
    from leaf `offset`, `cells` unknowns each)."""
    kx = K.createVecLeft()
    K.mult(x, kx)
    diagonal = kx.duplicate()
    diagonal.set(0.0)
    xs, ds = x.getArray(readonly=True), diagonal.getArray()
    for b in blocks:
        rows = slice((b.first - offset) * cells, (b.last - offset) * cells)
        part, out = b.K.createVecs()
        part.getArray()[:] = xs[rows]
        b.K.mult(part, out)
        ds[rows] = out.getArray(readonly=True)
        part.destroy(), out.destroy()
    off = kx.duplicate()
    kx.copy(off)
    off.axpy(-1.0, diagonal)
    shares = off.norm() / kx.norm(), off.sum() / kx.sum()
    for v in (kx, diagonal, off):
        v.destroy()
    return shares
