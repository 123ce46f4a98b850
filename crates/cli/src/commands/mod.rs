//! One module per subcommand; each turns parsed arguments into a [`crate::output::Report`].

pub mod crack_law;
pub mod jkr;
