use lagrange::mechanism;

#[mechanism]
pub struct NotAModule {
    pub x: f64,
}

fn main() {}
