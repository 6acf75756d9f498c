//! The geometry tests that go through more than one shape file, one file per subject; each
//! shape's own unit tests stay in its file. Shared helpers: [`support`] (scenes, marked
//! textures, random shapes and CSG) and [`test_support`](super::test_support) (the seeded
//! random generator and the crossings-flip-inside check, which the shapes' tests use too).

mod basic_shapes;
mod csg;
mod materials_and_uv;
mod meshes;
mod numeric_shapes;
mod support;
mod world;
