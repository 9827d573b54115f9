//! The finishing shape ns..nf shared by G70, G71, G72 and G73.
