//! `rime`: the terminal explorer and command-line tools.

fn main() {
    println!("rime");
}
