//! Console line editor and command grammar.
