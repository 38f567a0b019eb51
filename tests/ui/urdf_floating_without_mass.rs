// A floating base must carry mass: this file's root link has no inertial, nor anything welded to
// it.
#[lagrange::urdf("../../../../tests/urdf/two_link_arm.urdf", floating)]
pub mod robot {}

fn main() {}
