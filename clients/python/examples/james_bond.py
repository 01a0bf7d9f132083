# The pyoro example of the ORO wiki: it runs unchanged with this pyoro.
# Start a server first (swipl server/oro_server.pl); ORO_PORT=N picks
# another port than 6969.
from pyoro import Oro, OroServerError


def printer(content):
    print("God save the queen! " + content + " killed Bond!")


try:
    oro = Oro()
    oro.add("[bond rdf:type Human, bond rdfs:label \"Bond, James Bond\"]")
    print(oro.lookup("Bond, James Bond")[0])
    oro.subscribe(["?a kills bond"], printer)
    oro += "hrp2 kills bond"
except OroServerError as e:
    print("Oops! An error occured: %s" % e)
