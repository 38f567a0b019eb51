// The path is relative to the crate's manifest directory, here trybuild's project under target/.
#[lagrange::urdf("../../../../tests/urdf/bad/loop.urdf")]
pub mod robot {}

fn main() {}
