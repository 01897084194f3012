/* SPDX-License-Identifier: BSD-2-Clause */
/* Shape-function class: -mpm_shape_type selects N_I(x). Types give a 1D basis; d-dimensional
   functions are tensor products N_I(x) = prod_d N_{i_d}(x_d), with gradients by the product rule. */
#include "shapeimpl.h"

PETSC_EXTERN PetscErrorCode MPMShapeCreate_Linear(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_GIMP(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_CPDI(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_BSpline2(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_BSpline3(MPMShape);

static PetscBool MPMShapeRegisterAllCalled = PETSC_FALSE;

/* Registers every type of the shape functions: a new type is its file in impls/ plus its prototype and one line here. */
PetscErrorCode MPMShapeRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMShapeRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMShapeRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMShapeRegister(MPMSHAPELINEAR, MPMShapeCreate_Linear));
  PetscCall(MPMShapeRegister(MPMSHAPEGIMP, MPMShapeCreate_GIMP));
  PetscCall(MPMShapeRegister(MPMSHAPECPDI, MPMShapeCreate_CPDI));
  PetscCall(MPMShapeRegister(MPMSHAPEBSPLINE2, MPMShapeCreate_BSpline2));
  PetscCall(MPMShapeRegister(MPMSHAPEBSPLINE3, MPMShapeCreate_BSpline3));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscFunctionList MPMShapeList = NULL;

static PetscErrorCode MPMShapeReset(void *obj)
{
  MPMShape shape = (MPMShape)obj;

  PetscFunctionBegin;
  shape->needs_F       = PETSC_FALSE;
  shape->edge_gradient = PETSC_FALSE;
  shape->tent_mass     = PETSC_FALSE;
  shape->kernels       = NULL;
  shape->keeps         = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeViewClass(void *obj, PetscViewer viewer)
{
  MPMShape shape = (MPMShape)obj;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "ghost width %" PetscInt_FMT " cells%s\n", shape->ops.support(shape->data), shape->kernels ? ", specialised transfer kernels for 1D, 2D and 3D" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMShapeClass = {"shape function", "shape", "Shape functions", "MPMShape", "Shape function N_I(x)", MPMSHAPECPDI, &MPMShapeList, sizeof(MPMShapeOps), MPMShapeReset, NULL, MPMShapeViewClass, NULL, NULL, NULL};

MPM_CLASS_INTERFACE(MPMShape)

PetscErrorCode MPMShapeCreate(MPI_Comm comm, MPMShape *shape)
{
  PetscFunctionBegin;
  PetscCall(MPMShapeRegisterAll());
  PetscCall(MPMObjectCreate(comm, &MPMShapeClass, sizeof(struct _p_MPMShape), shape));
  PetscCall(MPMObjectSetOptionsPrefix(*shape, "mpm_"));
  PetscCall(MPMShapeSetType(*shape, MPMSHAPECPDI)); /* the default method: docs/shock-capturing.md */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Tells the type the grid and the points per cell per direction (GIMP and CPDI size the point domains with it). */
PetscErrorCode MPMShapeSetUp(MPMShape shape, const MPMGrid *g, PetscInt ppc)
{
  PetscFunctionBegin;
  if (shape->ops.setup) PetscCall(shape->ops.setup(shape, g, ppc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before the step's points to grid of the n points from local point p0 on (of nlocal), where the type keeps stencils
   (shape->keeps): room for nlocal points' stencils; with fresh, the scatter stores them (the specialised kernels'
   MPM_KEEP_STORE, the generic scatter's keepone), else (a body force, a crack field) their kept stencils are dropped,
   so that grid to points evaluates them again. Every gather that reads them (MPMGather, from MPMStep only) follows
   the same step's scatter over the same points, and nothing changes x_p, F_p or the domain scale in between. */
PetscErrorCode MPMShapeKeep(MPMShape shape, PetscInt nlocal, PetscInt p0, PetscInt n, PetscBool fresh)
{
  PetscFunctionBegin;
  if (shape->keeps) PetscCall(shape->ops.keep(shape, nlocal, p0, n, fresh));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeGetGhostWidth(MPMShape shape, PetscInt *width)
{
  PetscFunctionBegin;
  *width = shape->ops.support(shape->data);
  PetscFunctionReturn(PETSC_SUCCESS);
}
