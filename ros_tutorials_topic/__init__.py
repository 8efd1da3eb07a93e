"""The topic lesson: a publisher and a subscriber exchanging MsgTutorial messages,
and the classic talker/listener on ``chatter``."""
