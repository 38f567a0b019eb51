// The macro takes the file's path and, for a free-flying root link, `floating`.
#[lagrange::urdf("../../../../tests/urdf/two_link_arm.urdf", flying)]
pub mod robot {}

fn main() {}
