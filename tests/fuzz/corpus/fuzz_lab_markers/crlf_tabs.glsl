// TODO(a)
	//@solution
//@stub
//@ a
//@end
rest