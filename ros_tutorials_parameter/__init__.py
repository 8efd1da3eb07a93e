"""The parameter lesson: a service server whose operator is the parameter
``calculation_method``, its client, and a talker whose text is the parameter ``talker_str``."""
