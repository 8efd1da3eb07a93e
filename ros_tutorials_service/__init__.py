"""The service lesson: SrvTutorial server and client on ``ros_tutorial_srv``, and the
classic AddTwoInts server and client on ``add_two_ints``."""
