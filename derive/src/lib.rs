//! Proc-macro front end of the roll-coupling criterion emitter (issue 3; not yet written).
