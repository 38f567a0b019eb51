use lagrange::mechanism;

#[mechanism]
pub mod nothing {}

fn main() {}
