:- module(count_instances, []).
:- use_module(library(oro)).

/** <module> Example oro plugin: counting the instances of a class

Two RPC methods, for clients that want a number without transferring
the instances (getInstancesOf sends every instance with its label):

    countInstancesOf(String)        -> 3
    countDirectInstancesOf(String)  -> 1

Both count the named individuals of the class in the robot's model,
inferences included (countDirectInstancesOf only those whose most
specific class it is).  An unknown class, or something that is not a
class, answers the same NotFoundException as getInstancesOf.  Both only
read: they are declared read_only (no store write, no lock).

Load it with

    swipl server/oro_server.pl --plugin=examples/plugins/count_instances.pl

and try it with telnet:

    countInstancesOf
    Animal
    #end#
    ok
    3
    #end#
*/

oro_methods:method(countInstancesOf(string), taxonomy,
                   "Returns the number of instances (asserted or inferred) of a class.",
                   read_only(count_instances_of(oro_instances))).
oro_methods:method(countDirectInstancesOf(string), taxonomy,
                   "Returns the number of instances whose most specific class is the given one.",
                   read_only(count_instances_of(oro_direct_instances))).

%!  count_instances_of(:Question, +ClassName, -Reply) is det.
%
%   Reply is int(N), N being the number of instances Question
%   (oro_instances/3 or oro_direct_instances/3) gives for the class
%   ClassName (a name as a client writes it: `Animal`, `oro:Animal`).
%
%   @error existence_error(class, Class) if ClassName is not a class.

count_instances_of(Question, ClassName, int(N)) :-
    oro_name_iri(ClassName, Class),
    call(Question, myself, Class, Instances),
    length(Instances, N).
