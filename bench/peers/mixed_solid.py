"""The incompressible neo-Hookean solid in DOLFINx 0.5 (Debian's python3-dolfinx): mixed spaces,
residual form and a Newton loop with MUMPS, for the peer side of bench/peer-shell.

Units: those of the mesh and of c1 (the bench uses mm and MPa, so residuals are in N).

The displacement u and the pressure p are found from the stationary point of
    Pi(u, p) = int_Omega0 [ c1 (J^(-2/3) I1 - 3) - p (J - 1) ] dX,
    F = I + grad u, J = det F, I1 = tr(F^T F),
the same mixed form as plisse's (docs/theory/mixed_up.md): only the isochoric energy comes from
the material, and p is the multiplier of J = 1. Two element pairs:
  "mini"        u in P1 enriched by the cubic bubble of each tetrahedron, p in P1 (MINI); the
                bubble stays a global unknown here (plisse condenses it per element);
  "taylor-hood" u in P2, p in P1.
"""
import time

import ufl
from dolfinx import fem
from dolfinx.fem.petsc import (apply_lifting, assemble_matrix, assemble_vector, create_matrix,
                               create_vector, set_bc)
from petsc4py import PETSc

ELEMENTS = ("mini", "taylor-hood")


def mixed_space(mesh, element):
    """The space of (u, p) on `mesh` for an element pair of ELEMENTS."""
    cell = mesh.ufl_cell()
    linear = ufl.FiniteElement("Lagrange", cell, 1)
    if element == "mini":
        bubble = ufl.FiniteElement("Bubble", cell, 4)  # degree 4 on a tetrahedron: one cubic bubble
        displacement = ufl.VectorElement(ufl.EnrichedElement(linear, bubble))
    elif element == "taylor-hood":
        displacement = ufl.VectorElement("Lagrange", cell, 2)
    else:
        raise ValueError(f"element '{element}' is not one of {', '.join(ELEMENTS)}")
    return fem.FunctionSpace(mesh, ufl.MixedElement([displacement, linear]))


def neo_hookean_residual(state, c1, quadrature_degree):
    """The first variation of Pi at `state` (a Function of the mixed space) in the direction of
    the test functions, as a UFL form [N with mm, MPa]; also F and J of `state` for load terms.
    c1 [MPa] > 0: the shear modulus is 2 c1."""
    u, p = ufl.split(state)
    F = ufl.Identity(3) + ufl.grad(u)
    J = ufl.det(F)
    W = c1 * (J ** (-2.0 / 3.0) * ufl.inner(F, F) - 3.0)  # inner(F, F) = tr(F^T F) = I1
    dx = ufl.Measure("dx", metadata={"quadrature_degree": quadrature_degree})
    energy = (W - p * (J - 1.0)) * dx
    residual = ufl.derivative(energy, state, ufl.TestFunction(state.function_space))
    return residual, F, J


class NewtonMumps:
    """Full Newton on residual(state) = 0 with the exact tangent (the Gateaux derivative of the
    residual form) and a direct solve by MUMPS (LU through PETSc) at every iteration.

    Convergence, for each call of solve: ||R_k|| <= max(atol, rtol * R_ref) after at least one
    update, where ||R_k|| is the Euclidean norm of the residual with the Dirichlet rows holding the
    distance to their values and R_ref the largest residual norm seen in this call (at first the
    residual of the load step's initial state). The object keeps the time spent in assembly and in
    the linear solves [s]; it borrows residual, state and bcs."""

    def __init__(self, residual, state, bcs):
        self.state = state
        self.bcs = bcs
        self.residual_form = fem.form(residual)
        self.tangent_form = fem.form(ufl.derivative(residual, state))
        self.tangent = create_matrix(self.tangent_form)
        self.rhs = create_vector(self.residual_form)
        self.update = self.rhs.copy()
        self.ksp = PETSc.KSP().create(state.function_space.mesh.comm)
        self.ksp.setOperators(self.tangent)
        self.ksp.setType("preonly")
        self.ksp.getPC().setType("lu")
        self.ksp.getPC().setFactorSolverType("mumps")
        self.ksp.setFromOptions()
        self.assembly_time = 0.0
        self.linear_solve_time = 0.0

    def assemble_residual(self):
        """rhs = R(state), with rhs = state - g on the Dirichlet rows; returns its norm."""
        x = self.state.vector
        with self.rhs.localForm() as local:
            local.set(0.0)
        assemble_vector(self.rhs, self.residual_form)
        apply_lifting(self.rhs, [self.tangent_form], bcs=[self.bcs], x0=[x], scale=-1.0)
        self.rhs.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        set_bc(self.rhs, self.bcs, x, -1.0)
        return self.rhs.norm()

    def solve(self, rtol=1e-10, atol=1e-12, max_iterations=30):
        """Runs Newton from the current state; returns (iterations, final residual norm).
        Raises RuntimeError when it has not converged after max_iterations updates."""
        reference = 0.0
        for iteration in range(max_iterations + 1):
            start = time.perf_counter()
            norm = self.assemble_residual()
            self.assembly_time += time.perf_counter() - start
            reference = max(reference, norm)
            if iteration > 0 and norm <= max(atol, rtol * reference):
                return iteration, norm
            if iteration == max_iterations:
                break
            start = time.perf_counter()
            self.tangent.zeroEntries()
            assemble_matrix(self.tangent, self.tangent_form, bcs=self.bcs)
            self.tangent.assemble()
            self.assembly_time += time.perf_counter() - start
            start = time.perf_counter()
            self.ksp.solve(self.rhs, self.update)
            self.linear_solve_time += time.perf_counter() - start
            self.state.vector.axpy(-1.0, self.update)
            self.state.x.scatter_forward()
        raise RuntimeError(f"Newton: no convergence in {max_iterations} iterations "
                           f"(residual norm {norm:.3e})")


def n_unknowns(space):
    """The global number of unknowns of a (blocked) function space."""
    index_map = space.dofmap.index_map
    return index_map.size_global * space.dofmap.index_map_bs
