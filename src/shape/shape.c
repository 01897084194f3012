/* SPDX-License-Identifier: BSD-2-Clause */
/* Shape-function class: -mpm_shape_type selects N_I(x). Types give a 1D basis; d-dimensional
   functions are tensor products N_I(x) = prod_d N_{i_d}(x_d), with gradients by the product rule. */
#include "../petmpmimpl.h"

static PetscFunctionList MPMShapeList = NULL;

PetscErrorCode MPMShapeRegister(const char name[], PetscErrorCode (*create)(MPMShape))
{
  PetscFunctionBegin;
  PetscCall(PetscFunctionListAdd(&MPMShapeList, name, create));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeCreate(MPI_Comm comm, MPMShape *shape)
{
  PetscFunctionBegin;
  PetscCall(MPMInitializePackage());
  PetscCall(PetscNew(shape));
  (*shape)->comm = comm;
  PetscCall(MPMShapeSetType(*shape, MPMSHAPELINEAR));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeSetType(MPMShape shape, MPMShapeType type)
{
  PetscErrorCode (*create)(MPMShape);

  PetscFunctionBegin;
  PetscCall(MPMClassSetType(MPMShapeList, "shape function", "-mpm_shape_type", type, (PetscErrorCode(**)(void *)) & create));
  if (shape->ops.destroy) PetscCall(shape->ops.destroy(shape));
  PetscCall(PetscMemzero(&shape->ops, sizeof(shape->ops)));
  shape->data = NULL;
  PetscCall(PetscStrncpy(shape->type_name, type, sizeof(shape->type_name)));
  PetscCall(create(shape));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeSetFromOptions(MPMShape shape)
{
  char      type[MPM_MAX_NAME];
  PetscBool set;

  PetscFunctionBegin;
  PetscOptionsBegin(shape->comm, NULL, "Shape functions", "MPMShape");
  PetscCall(PetscOptionsFList("-mpm_shape_type", "Shape function N_I(x)", "MPMShapeSetType", MPMShapeList, shape->type_name, type, sizeof(type), &set));
  if (set) PetscCall(MPMShapeSetType(shape, type));
  if (shape->ops.setfromoptions) PetscCall(shape->ops.setfromoptions(shape, PetscOptionsObject));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeView(MPMShape shape, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Shape functions: %s (ghost width %" PetscInt_FMT ")\n", shape->type_name, shape->ops.support(shape->data)));
  if (shape->ops.view) PetscCall(shape->ops.view(shape, viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeGetGhostWidth(MPMShape shape, PetscInt *width)
{
  PetscFunctionBegin;
  *width = shape->ops.support(shape->data);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeDestroy(MPMShape *shape)
{
  PetscFunctionBegin;
  if (!*shape) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*shape)->ops.destroy) PetscCall((*shape)->ops.destroy(*shape));
  PetscCall(PetscFree(*shape));
  PetscFunctionReturn(PETSC_SUCCESS);
}
