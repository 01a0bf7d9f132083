:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(pairs)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro)).
:- use_module(library(oro/reason/oro_reason),
              [oro_compiled_schema/2, oro_shared_schema/2]).
:- use_module(library(oro/oro_store),
              [oro_store_write/2, oro_store_assert/3, oro_store_retract/2,
               oro_graph/3, oro_load_ontology/1, oro_store_rebuild/0]).
:- use_module(library(settings)).
:- use_module(library(random)).
:- use_module(library(aggregate)).

/*  Tests of events (ORO-SPEC §1.4, §7, vectors §13.10, per-agent events
    of §13.11 and the seed session §13.13), over real sockets on
    127.0.0.1 and through the Prolog API (oro_subscribe/7,8).  Unlike
    ORO 0.8.2 (§1.4 [QUIRK]), a watcher whose only subscribers have
    disconnected is dropped, and so is a subscriber that falls behind
    (a connection is closed, a planner's subscription is told).

    Most tests use two connections: A registers, B makes the changes, A
    receives the events.  That nothing (more) fired is never asserted
    with a sleep: A also subscribes to a *sentinel* watcher, registered
    after the watchers under test,

        NEW_INSTANCE ON_TRUE mark [?mark rdf:type EvMarker]

    and after a change B adds a new marker; the events A receives before
    the sentinel's firing for that marker are exactly those the change
    (and the marker's own change) caused, because a subscriber receives
    the firings of one change in registration order and changes in
    commit order.  Expected events come within 5 s (bounded waits).

    Each unit starts its own server (port 0) and every test starts from
    oro_reset/0; helpers are prefixed ev_ (all test files load into
    user), those shared with the other test files are in
    oro_test_support.pl.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_events.pl
*/

                 /*******************************
                 *     SERVER AND CONNECTIONS   *
                 *******************************/

%   The unit's server (test_server_start/1, test_server_stop/0): on
%   the test ontology or the common-sense one.

ev_start_testsuite :-
    test_server_start_testsuite.

ev_start_commonsense :-
    test_server_start([commonsense(true)]).

ev_stop :-
    test_server_stop.

%   ev_fresh: the store as loaded, no watcher, no connection left over
%   from the previous test.

ev_fresh :-
    test_server_wait_idle,
    oro_reset.

%   ev_connected(-Conns, :Goal): run Goal once with Conns, a list of
%   new connections (its length fixed by the caller), closed afterwards
%   whatever happens.

:- meta_predicate ev_connected(?, 0).

ev_connected(Conns, Goal) :-
    must_be(list, Conns),
    test_server_port(Port),
    setup_call_cleanup(
        maplist(oro_connect(Port), Conns),
        once(Goal),
        maplist(ev_disconnect, Conns)).

ev_disconnect(Conn) :-
    catch(oro_disconnect(Conn), _, true).

                 /*******************************
                 *           REQUESTS           *
                 *******************************/

%   ev_ok(+Conn, +Method, +Params[, -Value]): a request that must be
%   answered `ok`.

ev_ok(Conn, Method, Params) :-
    ev_ok(Conn, Method, Params, _).

ev_ok(Conn, Method, Params, Value) :-
    oro_call(Conn, Method, Params, Reply, 10),
    (   Reply = ok(Value0)
    ->  Value = Value0
    ;   throw(ev_unexpected_reply(Method, Params, Reply))
    ).

%   ev_register(+Conn, +Params, -Id): registerEvent, Id a UUID.

ev_register(Conn, Params, Id) :-
    ev_ok(Conn, registerEvent, Params, Id),
    (   ev_uuid(Id)
    ->  true
    ;   throw(ev_not_a_uuid(Params, Id))
    ).

%   ev_uuid(+Text) is semidet: Text is a UUID as Java prints it:
%   lowercase hex digits in groups of 8-4-4-4-12.

ev_uuid(Text) :-
    string(Text),
    split_string(Text, "-", "", Groups),
    maplist(string_length, Groups, [8, 4, 4, 4, 12]),
    string_codes(Text, Codes),
    forall(member(C, Codes),
           ( C == 0'-
           ; code_type(C, digit)
           ; between(0'a, 0'f, C)
           )).

%   ev_exchange(+Conn, +Method, +Params, +N, -Messages): send a request
%   and read the next N messages, in arrival order.

ev_exchange(Conn, Method, Params, N, Messages) :-
    oro_send(Conn, Method, Params),
    length(Messages, N),
    maplist(ev_receive(Conn), Messages).

ev_receive(Conn, Message) :-
    oro_receive(Conn, Message, 5).

%   ev_first_value(+Messages, -Value): the value of a leading ok
%   reply, else `none`.

ev_first_value([ok(Value)|_], Value) :-
    !.
ev_first_value(_, none).

%   ev_values(+Content, -Values): the ids of an event's content line
%   (`["a","b"]`), as a sorted list of strings.

ev_values(Content, Values) :-
    catch(test_json(Content, List), _, fail),
    is_list(List),
    maplist(string, List),
    !,
    msort(List, Values).
ev_values(Content, not_a_list(Content)).

%   ev_parsed(+Event0, -Event): Id-Content with the content parsed by
%   ev_values/2 (the order of the ids carries no meaning).

ev_parsed(Id-Content, Id-Values) :-
    !,
    ev_values(Content, Values).
ev_parsed(Event, Event).

                 /*******************************
                 *     SENTINEL AND STEPS       *
                 *******************************/

%   ev_sentinel(+Conn, -Id): subscribe Conn to the sentinel watcher.

ev_sentinel(Conn, Id) :-
    ev_register(Conn, ["NEW_INSTANCE", "ON_TRUE", "mark",
                       "[?mark rdf:type EvMarker]"], Id).

%   ev_agent_sentinel(+Conn, -Id): the same in the registry of
%   registerEventForAgent (on the robot's model).

ev_agent_sentinel(Conn, Id) :-
    ev_ok(Conn, registerEventForAgent, ["myself", "NEW_INSTANCE", "ON_TRUE", "mark",
                                        "[?mark rdf:type EvMarker]"], Id).

%   ev_marker(-Statement, -Content): a new marker statement, and the
%   content of the sentinel's event it causes.

ev_marker(Statement, Content) :-
    flag(ev_mark, N, N+1),
    format(string(Statement), "[ev_mark_~d rdf:type EvMarker]", [N]),
    format(string(Content), "[\"ev_mark_~d\"]", [N]).

%   ev_step(+Listener, +Actor, +Sentinel, +Method, +Params, -Events):
%   Actor runs Method(Params), then adds a marker; Events are the
%   events Listener receives before the sentinel's firing for the
%   marker, as Id-Content pairs (then `timeout` if it never comes).

ev_step(Listener, Actor, Sentinel, Method, Params, Events) :-
    ev_ok(Actor, Method, Params),
    ev_settle(Listener, Actor, Sentinel, Events).

%   ev_settle(+Listener, +Actor, +Sentinel, -Events): the same with no
%   change but the marker's.

ev_settle(Listener, Actor, Sentinel, Events) :-
    ev_marker(Statement, Content),
    ev_ok(Actor, add, [Statement]),
    ev_drain(Listener, Sentinel, Content, 200, Events).

ev_drain(Listener, Sentinel, Content, Max, Events) :-
    oro_next_event(Listener, Event, 5),
    (   Event = event(Sentinel, Content)
    ->  Events = []
    ;   Max =< 0
    ->  Events = [too_many]
    ;   Event = event(Id, C)
    ->  Events = [Id-C|Rest],
        Max1 is Max - 1,
        ev_drain(Listener, Sentinel, Content, Max1, Rest)
    ;   Events = [Event]
    ).

%   ev_raw_step(+Conn, +Sentinel, +Method, +Params, -Messages): on one
%   connection, send Method(Params), read the next message (its reply,
%   unless an event came first), then add a marker and read until the
%   sentinel's firing: Messages is the reply followed by every event
%   received before the sentinel's (the marker's own `ok` left out).

ev_raw_step(Conn, Sentinel, Method, Params, [Reply|Events]) :-
    oro_send(Conn, Method, Params),
    ev_receive(Conn, Reply),
    ev_marker(Statement, Content),
    oro_send(Conn, add, [Statement]),
    ev_raw_drain(Conn, Sentinel, Content, false, 200, Events).

ev_raw_drain(Conn, Sentinel, Content, SeenOk, Max, Events) :-
    ev_receive(Conn, Message),
    (   SeenOk == false,
        Message == ok("")
    ->  ev_raw_drain(Conn, Sentinel, Content, true, Max, Events)
    ;   SeenOk == true,
        Message = event(Sentinel, Content)
    ->  Events = []
    ;   Max =< 0
    ->  Events = [too_many]
    ;   memberchk(Message, [timeout, end_of_file])
    ->  Events = [Message]
    ;   Events = [Message|Rest],
        Max1 is Max - 1,
        ev_raw_drain(Conn, Sentinel, Content, SeenOk, Max1, Rest)
    ).

%   ev_steps(+Listener, +Actor, +Sentinel, +Steps, -EventLists):
%   ev_step/6 for each Method-Params of Steps (settle for `settle`).

ev_steps(Listener, Actor, Sentinel, Steps, EventLists) :-
    maplist(ev_step_(Listener, Actor, Sentinel), Steps, EventLists).

ev_step_(Listener, Actor, Sentinel, settle, Events) :-
    !,
    ev_settle(Listener, Actor, Sentinel, Events).
ev_step_(Listener, Actor, Sentinel, Method-Params, Events) :-
    ev_step(Listener, Actor, Sentinel, Method, Params, Events).

%   ev_watch(+Type, +Trigger, +VarAndPatterns, -EventLists, +Steps):
%   on two fresh connections, A registers one watcher and the
%   sentinel, B runs Steps; EventLists are A's events per step, with
%   the watcher's id replaced by `w`.

ev_watch(Type, Trigger, VarAndPatterns, Steps, EventLists) :-
    ev_connected([A, B],
                 ( ev_register(A, [Type, Trigger|VarAndPatterns], Id),
                   ev_sentinel(A, S),
                   ev_steps(A, B, S, Steps, EventLists0)
                 )),
    maplist(maplist(ev_name_id(Id, w)), EventLists0, EventLists).

ev_name_id(Id, Name, Event0, Event) :-
    (   Event0 = Id-Content
    ->  Event = Name-Content
    ;   Event = Event0
    ).

                 /*******************************
                 *         FACT_CHECKING        *
                 *******************************/

:- begin_tests(events_fact_checking,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

test(on_true, [ setup(ev_fresh),
                true(Events == [[w-""], [], [w-""], []])
              ]) :-
    ev_watch("FACT_CHECKING", "ON_TRUE", ["[chicken has teeth]"],
             [ add-["[chicken has teeth]"],
               remove-["[chicken has teeth]"],
               add-["[chicken has teeth]"],
               add-["[paris loves dancing]"]
             ], Events).
test(on_true_already_true_fires_at_first_change,
     [ setup(ev_fresh),
       true(Events == [[w-""], [], []])
     ]) :-
    ev_watch("FACT_CHECKING", "ON_TRUE", ["[gorilla eats apple]"],
             [ add-["[paris loves dancing]"],
               add-["[paris loves cheese]"],
               settle
             ], Events).
test(on_true_conjunction_shared_variable,
     [ setup(ev_fresh),
       true(Events == [[], [], [w-""]])
     ]) :-
    ev_watch("FACT_CHECKING", "ON_TRUE",
             ["[?a rdf:type Monkey, ?a eats grass]"],
             [ settle,
               add-["[coco eats grass]"],          % coco is no Monkey
               add-["[baboon eats grass]"]
             ], Events).
test(on_false, [ setup(ev_fresh),
                 true(Events == [[], [], [w-""], [], []])
               ]) :-
    ev_watch("FACT_CHECKING", "ON_FALSE", ["[chicken has teeth]"],
             [ settle,                            % false at the first change: no edge
               add-["[chicken has teeth]"],
               remove-["[chicken has teeth]"],
               remove-["[chicken has teeth]"],
               settle
             ], Events).
test(on_false_already_true, [ setup(ev_fresh),
                              true(Events == [[], [w-""], []])
                            ]) :-
    ev_watch("FACT_CHECKING", "ON_FALSE", ["[gorilla eats apple]"],
             [ settle,
               remove-["[gorilla eats apple]"],
               add-["[paris loves dancing]"]
             ], Events).
test(on_toggle, [ setup(ev_fresh),
                  true(Events == [[], [w-""], [], [w-""], [], [w-""]])
                ]) :-
    ev_watch("FACT_CHECKING", "ON_TOGGLE", ["[chicken has teeth]"],
             [ settle,
               add-["[chicken has teeth]"],
               add-["[chicken has teeth]"],
               remove-["[chicken has teeth]"],
               remove-["[chicken has teeth]"],
               add-["[chicken has teeth]"]
             ], Events).
test(on_toggle_already_true_fires_at_first_change,
     [ setup(ev_fresh),
       true(Events == [[w-""], [], [w-""]])
     ]) :-
    ev_watch("FACT_CHECKING", "ON_TOGGLE", ["[gorilla eats apple]"],
             [ settle,
               settle,
               remove-["[gorilla eats apple]"]
             ], Events).
test(on_true_one_shot, [ setup(ev_fresh),
                         true(Events-Cleared ==
                              [[w-""], [], []]-
                              error("laas.openrobots.ontology.exceptions.EventNotFoundException",
                                    Message))
                       ]) :-
    ev_connected([A, B],
                 ( ev_register(A, ["FACT_CHECKING", "ON_TRUE_ONE_SHOT",
                                   "[chicken has teeth]"], Id),
                   ev_sentinel(A, S),
                   ev_steps(A, B, S,
                            [ add-["[chicken has teeth]"],
                              remove-["[chicken has teeth]"],
                              add-["[chicken has teeth]"]
                            ], Events0),
                   oro_call(A, clearEvent, [Id], Cleared)
                 )),
    maplist(maplist(ev_name_id(Id, w)), Events0, Events),
    format(string(Message), "Event ~w does not exist in the model", [Id]).
test(on_true_one_shot_already_true,
     [ setup(ev_fresh),
       true(Events == [[w-""], []])
     ]) :-
    ev_watch("FACT_CHECKING", "ON_TRUE_ONE_SHOT", ["[gorilla eats apple]"],
             [ settle,
               settle
             ], Events).
test(on_false_one_shot_fires_at_any_first_change,
     [ setup(ev_fresh),
       true(Events == [[w-""], [], [], []])
     ]) :-
    ev_watch("FACT_CHECKING", "ON_FALSE_ONE_SHOT", ["[chicken has teeth]"],
             [ add-["[paris loves dancing]"],
               add-["[chicken has teeth]"],
               remove-["[chicken has teeth]"],
               settle
             ], Events).
test(on_false_one_shot_on_true_pattern,
     [ setup(ev_fresh),
       true(Events == [[], [w-""], [], []])
     ]) :-
    ev_watch("FACT_CHECKING", "ON_FALSE_ONE_SHOT", ["[gorilla eats apple]"],
             [ settle,
               remove-["[gorilla eats apple]"],
               add-["[gorilla eats apple]"],
               remove-["[gorilla eats apple]"]
             ], Events).
test(batch_is_one_change, [ setup(ev_fresh),
                            true(Events == [[w-""], [w-""], []])
                          ]) :-
    ev_watch("FACT_CHECKING", "ON_TOGGLE",
             ["[chicken has teeth, chicken has feathers]"],
             [ add-["[chicken has teeth, chicken has feathers, chicken has wings]"],
               remove-["[chicken has teeth, chicken has feathers]"],
               add-["[chicken has teeth]"]
             ], Events).
test(lower_case_type_and_trigger, [ setup(ev_fresh),
                                    true(Events == [[w-""]])
                                  ]) :-
    ev_watch("fact_checking", "on_true", ["[chicken has teeth]"],
             [ add-["[chicken has teeth]"]
             ], Events).

:- end_tests(events_fact_checking).

                 /*******************************
                 *         NEW_INSTANCE         *
                 *******************************/

:- begin_tests(events_new_instance,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

test(on_true, [ setup(ev_fresh),
                true(Events == [[], [w-"[\"banana\"]"], [], [w-"[\"grass\"]"]])
              ]) :-
    % §13.10: the initial binding (apple, from gorilla) is not reported.
    ev_watch("NEW_INSTANCE", "ON_TRUE", ["b", "[?a rdf:type Monkey, ?a eats ?b]"],
             [ add-["[coco rdf:type Monkey]"],
               add-["[coco eats banana]"],
               add-["[coco eats banana]"],
               add-["[baboon eats grass]"]
             ], Events).
test(variable_with_question_mark, [ setup(ev_fresh),
                                    true(Events == [[w-"[\"coco\"]"]])
                                  ]) :-
    ev_watch("NEW_INSTANCE", "ON_TRUE", ["?a", "[?a rdf:type Monkey]"],
             [ add-["[coco rdf:type Monkey]"]
             ], Events).
test(on_true_batch_one_event, [ setup(ev_fresh),
                                true(Events == [w-["m1", "m2"]])
                              ]) :-
    ev_watch("NEW_INSTANCE", "ON_TRUE", ["a", "[?a rdf:type Monkey]"],
             [ add-["[m1 rdf:type Monkey, m2 rdf:type Monkey]"]
             ], [Events0]),
    maplist(ev_parsed, Events0, Events).
test(type_only_class_as_sub_class,   % a new class, only used as a type
     [ setup(ev_fresh),                 % (so is EvMarker, of ev_marker/2)
       true(Events == [[w-"[\"Gizmo\"]", w-"[\"EvMarker\"]"]])
     ]) :-
    ev_watch("NEW_INSTANCE", "ON_TRUE", ["c", "[?c rdfs:subClassOf owl:Thing]"],
             [ add-["[x2 rdf:type Gizmo]"]
             ], Events).
test(on_true_one_text_once,          % "robot"@en and "robot"@fr
     [ setup(ev_fresh),
       true(Events == [[w-"[\"robot\"]"]])
     ]) :-
    ev_watch("NEW_INSTANCE", "ON_TRUE", ["l", "[o3 rdfs:label ?l]"],
             [ add-["[o3 rdfs:label \"robot\"@en, o3 rdfs:label \"robot\"@fr]"]
             ], Events).
test(on_false, [ setup(ev_fresh),
                 true(Events == [[], [], [w-"[\"coco\"]"], [w-"[\"gorilla\"]"]])
               ]) :-
    ev_watch("NEW_INSTANCE", "ON_FALSE", ["a", "[?a rdf:type Monkey]"],
             [ add-["[coco rdf:type Monkey]"],
               add-["[bobo rdf:type Monkey]"],
               remove-["[coco rdf:type Monkey]"],
               remove-["[gorilla rdf:type Monkey]"]
             ], Events).
test(on_toggle, [ setup(ev_fresh),
                  true(Events == [[w-"[\"coco\"]"], [], [w-"[\"coco\"]"]])
                ]) :-
    ev_watch("NEW_INSTANCE", "ON_TOGGLE", ["a", "[?a rdf:type Monkey]"],
             [ add-["[coco rdf:type Monkey]"],
               add-["[coco rdf:type Monkey]"],
               remove-["[coco rdf:type Monkey]"]
             ], Events).
test(on_toggle_removed_then_added, [ setup(ev_fresh),
                                     true(Events == [[w-"[\"35\"]", w-"[\"36\"]"]])
                                   ]) :-
    % One change (update of a functional property) removes a value and
    % adds one: the removed list first, then the added one.
    ev_watch("NEW_INSTANCE", "ON_TOGGLE", ["v", "[baboon age ?v]"],
             [ update-["[baboon age 36]"]
             ], Events).
test(on_true_one_shot, [ setup(ev_fresh),
                         true(Events == [[], [w-"[\"coco\"]"], [], []])
                       ]) :-
    ev_watch("NEW_INSTANCE", "ON_TRUE_ONE_SHOT", ["a", "[?a rdf:type Monkey]"],
             [ remove-["[gorilla rdf:type Monkey]"],
               add-["[coco rdf:type Monkey]"],
               add-["[bobo rdf:type Monkey]"],
               add-["[gorilla rdf:type Monkey]"]
             ], Events).
test(on_false_one_shot, [ setup(ev_fresh),
                          true(Events == [[], [w-"[\"coco\"]"], []])
                        ]) :-
    ev_watch("NEW_INSTANCE", "ON_FALSE_ONE_SHOT", ["a", "[?a rdf:type Monkey]"],
             [ add-["[coco rdf:type Monkey, bobo rdf:type Monkey]"],
               remove-["[coco rdf:type Monkey]"],
               remove-["[bobo rdf:type Monkey]"]
             ], Events).

:- end_tests(events_new_instance).

                 /*******************************
                 *      NEW_CLASS_INSTANCE      *
                 *******************************/

:- begin_tests(events_new_class_instance,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

test(on_true, [ setup(ev_fresh),
                true(Events == [[w-"[\"coco\"]"], [w-"[\"bumbo\"]"], [], []])
              ]) :-
    % §13.10; bumbo is a Monkey by the domain of climbsOn.
    ev_watch("NEW_CLASS_INSTANCE", "ON_TRUE", ["[Monkey]"],
             [ add-["[coco rdf:type Monkey]"],
               add-["[bumbo climbsOn old_oak]"],
               add-["[baboon climbsOn old_oak]"],   % baboon was one already
               add-["[cow eats old_oak]"]           % an Animal, no Monkey
             ], Events).
test(removal_updates_the_set_silently, [ setup(ev_fresh),
                                         true(Events == [[w-"[\"coco\"]"], [], [w-"[\"coco\"]"]])
                                       ]) :-
    ev_watch("NEW_CLASS_INSTANCE", "ON_TRUE", ["[Monkey]"],
             [ add-["[coco rdf:type Monkey]"],
               remove-["[coco rdf:type Monkey]"],
               add-["[coco rdf:type Monkey]"]
             ], Events).
test(subclass_instances, [ setup(ev_fresh),
                           true(Events == [[], [w-"[\"lemmy\"]"]])
                         ]) :-
    ev_watch("NEW_CLASS_INSTANCE", "ON_TRUE", ["[Monkey]"],
             [ add-["[lemmy rdf:type Lemur]"],
               add-["[Lemur rdfs:subClassOf Monkey]"]
             ], Events).
test(on_true_one_shot, [ setup(ev_fresh),
                         true(Events == [[w-"[\"coco\"]"], []])
                       ]) :-
    ev_watch("NEW_CLASS_INSTANCE", "ON_TRUE_ONE_SHOT", ["[Monkey]"],
             [ add-["[coco rdf:type Monkey]"],
               add-["[bobo rdf:type Monkey]"]
             ], Events).
test(other_triggers_never_fire, [ setup(ev_fresh),
                                  true(Events == [[], [], [], []])
                                ]) :-
    ev_connected([A, B],
                 ( forall(member(T, ["ON_FALSE", "ON_TOGGLE", "ON_FALSE_ONE_SHOT"]),
                          ev_register(A, ["NEW_CLASS_INSTANCE", T, "[Monkey]"], _)),
                   ev_sentinel(A, S),
                   ev_steps(A, B, S,
                            [ add-["[coco rdf:type Monkey]"],
                              remove-["[coco rdf:type Monkey]"],
                              remove-["[gorilla rdf:type Monkey]"],
                              add-["[bumbo climbsOn old_oak]"]
                            ], Events)
                 )).

:- end_tests(events_new_class_instance).

                 /*******************************
                 *          INFERENCE           *
                 *******************************/

:- begin_tests(events_inference,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

test(schema_change_adds_and_removes, [ setup(ev_fresh),
                                       true(Events == [[], [w-"[\"sparrow\"]"],
                                                       [w-"[\"sparrow\"]"]])
                                     ]) :-
    ev_watch("NEW_INSTANCE", "ON_TOGGLE", ["x", "[?x rdf:type Animal]"],
             [ add-["[sparrow rdf:type Bird]"],
               add-["[Bird rdfs:subClassOf Animal]"],
               clear-["[Bird rdfs:subClassOf Animal]"]
             ], Events).
test(inverse_property, [ setup(ev_fresh),
                         true(Events == [[], [w-""]])
                       ]) :-
    ev_watch("FACT_CHECKING", "ON_TRUE", ["[table isUnder cup]"],
             [ settle,                            % evaluated once: false
               add-["[cup isOn table]"]
             ], Events).
test(transitive_subproperty, [ setup(ev_fresh),
                               true(Events == [[], [w-"[\"cup\",\"table\"]"]])
                             ]) :-
    ev_watch("NEW_INSTANCE", "ON_TRUE", ["x", "[?x isAt room]"],
             [ add-["[cup isOn table]"],
               add-["[table isAt room]"]
             ], Events).
test(range_inference, [ setup(ev_fresh),
                        true(Events == [[w-"[\"old_oak\"]"]])
                      ]) :-
    ev_watch("NEW_CLASS_INSTANCE", "ON_TRUE", ["[Plant]"],
             [ add-["[bumbo climbsOn old_oak]"]
             ], Events).

:- end_tests(events_inference).

                 /*******************************
                 *   REGISTRATION AND CLEARING  *
                 *******************************/

:- begin_tests(events_registration,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

%   The vectors of §13.10, on one connection as the spec shows them:
%   each change's reply, then the events it caused.  (The sentinel is
%   our addition, for the "no event" steps.)

test(vector_fact_checking,
     [ setup(ev_fresh),
       true(Got == Expected)
     ]) :-
    ev_connected([C],
                 ( ev_exchange(C, registerEvent, ["FACT_CHECKING", "ON_TRUE",
                                                  "[chicken has teeth]"], 1, M1),
                   ev_exchange(C, registerEvent, ["FACT_CHECKING", "ON_FALSE_ONE_SHOT",
                                                  "[chicken has teeth]"], 1, M2),
                   ev_sentinel(C, S),
                   ev_raw_step(C, S, add, ["[paris loves dancing]"], M3),
                   ev_raw_step(C, S, add, ["[paris prefers listening_to_music]"], M4),
                   ev_raw_step(C, S, add, ["[chicken has teeth]"], M5),
                   ev_raw_step(C, S, remove, ["[chicken has teeth]"], M6),
                   ev_exchange(C, registerEvent, ["FACT_CHECKING", "ON_TRUE",
                                                  "[?a rdf:type Monkey, ?a eats grass]"], 1, M7),
                   ev_raw_step(C, S, add, ["[baboon eats grass]"], M8),
                   ev_exchange(C, registerEvent, ["FACT_CHECKING", "ON_TRUE",
                                                  "[chicken has teeth]"], 1, M9)
                 )),
    ev_first_value(M1, U1),
    ev_first_value(M2, U2),
    ev_first_value(M7, U3),
    Got = [M1, M2, M3, M4, M5, M6, M7, M8, M9],
    Expected = [ [ok(U1)],
                 [ok(U2)],
                 [ok(""), event(U2, "")],   % false: ON_FALSE_ONE_SHOT fires
                 [ok("")],                  % and was removed
                 [ok(""), event(U1, "")],
                 [ok("")],                  % ON_TRUE only
                 [ok(U3)],
                 [ok(""), event(U3, "")],
                 [ok(U1)]                   % identical watcher: same id
               ].
test(vector_ids_are_uuids, [ setup(ev_fresh),
                             true(Checks == [true, true, true])
                           ]) :-
    ev_connected([C],
                 ( ev_ok(C, registerEvent, ["FACT_CHECKING", "ON_TRUE",
                                            "[chicken has teeth]"], U1),
                   ev_ok(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "a",
                                            "[?a rdf:type Monkey]"], U2),
                   ev_ok(C, registerEvent, ["NEW_CLASS_INSTANCE", "ON_TRUE",
                                            "[Monkey]"], U3)
                 )),
    maplist(ev_check(ev_uuid), [U1, U2, U3], Checks).
test(vector_clear_event, [ setup(ev_fresh),
                           true(Got == Expected)
                         ]) :-
    ev_connected([C],
                 ( ev_exchange(C, registerEvent, ["FACT_CHECKING", "ON_TRUE",
                                                  "[chicken has teeth]"], 1, M1),
                   ev_first_value(M1, U1),
                   ev_exchange(C, clearEvent, [U1], 1, M2),
                   ev_sentinel(C, S),
                   ev_raw_step(C, S, add, ["[chicken has teeth]"], M3),
                   ev_raw_step(C, S, remove, ["[chicken has teeth]"], M4),
                   ev_exchange(C, clearEvent, [U1], 1, M5)
                 )),
    format(string(NotFound), "Event ~w does not exist in the model", [U1]),
    Got = [M2, M3, M4, M5],
    Expected = [ [ok("")],
                 [ok("")],
                 [ok("")],
                 [error("laas.openrobots.ontology.exceptions.EventNotFoundException",
                        NotFound)]
               ].
test(vector_new_instance, [ setup(ev_fresh),
                            true(Got == Expected)
                          ]) :-
    ev_connected([C],
                 ( ev_exchange(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "b",
                                                  "[?a rdf:type Monkey, ?a eats ?b]"], 1, M1),
                   ev_sentinel(C, S),
                   ev_raw_step(C, S, add, ["[coco rdf:type Monkey]"], M2),
                   ev_raw_step(C, S, add, ["[coco eats banana]"], M3),
                   ev_raw_step(C, S, add, ["[coco eats banana]"], M4)
                 )),
    ev_first_value(M1, U3),
    Got = [M1, M2, M3, M4],
    Expected = [ [ok(U3)],
                 [ok("")],
                 [ok(""), event(U3, "[\"banana\"]")],
                 [ok("")]
               ].
test(vector_new_class_instance, [ setup(ev_fresh),
                                  true(Got == Expected)
                                ]) :-
    ev_connected([C],
                 ( ev_exchange(C, registerEvent, ["NEW_CLASS_INSTANCE", "ON_TRUE",
                                                  "[Monkey]"], 1, M1),
                   ev_exchange(C, add, ["[coco rdf:type Monkey]"], 2, M2),
                   ev_exchange(C, add, ["[bumbo climbsOn old_oak]"], 2, M3)
                 )),
    ev_first_value(M1, U4),
    Got = [M1, M2, M3],
    Expected = [ [ok(U4)],
                 [ok(""), event(U4, "[\"coco\"]")],
                 [ok(""), event(U4, "[\"bumbo\"]")]
               ].
test(clear_events, [ setup(ev_fresh),
                     true(Got == [[], [], [], []]-new_id)
                   ]) :-
    ev_connected([A, B],
                 ( ev_register(A, ["FACT_CHECKING", "ON_TOGGLE", "[chicken has teeth]"], _),
                   ev_register(A, ["NEW_INSTANCE", "ON_TRUE", "a", "[?a rdf:type Monkey]"], _),
                   ev_register(A, ["NEW_CLASS_INSTANCE", "ON_TRUE", "[Monkey]"], _),
                   ev_sentinel(A, S0),
                   ev_ok(B, clearEvents, []),
                   ev_sentinel(A, S),          % registered anew
                   ev_steps(A, B, S,
                            [ add-["[chicken has teeth]"],
                              add-["[coco rdf:type Monkey]"],
                              remove-["[chicken has teeth]"],
                              settle
                            ], Events)
                 )),
    (   S \== S0
    ->  NewId = new_id
    ;   NewId = same_id
    ),
    Got = Events-NewId.
test(clear_event_unknown, [ setup(ev_fresh),
                            true(Reply == error("laas.openrobots.ontology.exceptions.EventNotFoundException",
                                                "Event 0b5a8a9e-3d1c-4c2e-9d7e-2f1a6b3c4d5e does not exist in the model"))
                          ]) :-
    ev_connected([C], oro_call(C, clearEvent, ["0b5a8a9e-3d1c-4c2e-9d7e-2f1a6b3c4d5e"], Reply)).
test(clear_event_malformed_uuid, [ setup(ev_fresh),
                                   true(Reply == error("java.lang.IllegalArgumentException",
                                                       "Invalid UUID string: not-a-uuid"))
                                 ]) :-
    ev_connected([C], oro_call(C, clearEvent, ["not-a-uuid"], Reply)).
test(clear_event_upper_case_uuid, [ setup(ev_fresh),
                                    true(r(First, Again) ==
                                         r(ok(""), "laas.openrobots.ontology.exceptions.EventNotFoundException"))
                                  ]) :-
    % A UUID is the same in either case (Java's UUID.fromString).
    ev_connected([C],
                 ( ev_register(C, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U),
                   string_upper(U, Upper),
                   oro_call(C, clearEvent, [Upper], First),
                   oro_call(C, clearEvent, [U], Reply),
                   test_error_name(Reply, Again)
                 )).
test(clear_event_non_hex_uuid, [ setup(ev_fresh),
                                 true(Reply == error("java.lang.IllegalArgumentException",
                                                     "Invalid UUID string: zzzzzzzz-0000-4000-8000-000000000000"))
                               ]) :-
    ev_connected([C], oro_call(C, clearEvent, ["zzzzzzzz-0000-4000-8000-000000000000"], Reply)).
test(clear_event_from_another_connection, [ setup(ev_fresh),
                                            true(Events == [[]])
                                          ]) :-
    ev_connected([A, B],
                 ( ev_register(A, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U),
                   ev_sentinel(A, S),
                   ev_ok(B, clearEvent, [U]),
                   ev_steps(A, B, S, [add-["[chicken has teeth]"]], Events)
                 )).
test(error_event_type, [ setup(ev_fresh),
                         true(Reply == error("laas.openrobots.ontology.exceptions.InvalidEventDescriptorException",
                                             "Invalid event type. One of [FACT_CHECKING, NEW_CLASS_INSTANCE, NEW_INSTANCE] was expected. Got FOO instead."))
                       ]) :-
    ev_connected([C], oro_call(C, registerEvent, ["FOO", "ON_TRUE", "[x y z]"], Reply)).
test(error_trigger, [ setup(ev_fresh),
                      true(Reply == error("laas.openrobots.ontology.exceptions.InvalidEventDescriptorException",
                                          "Invalid event triggering type. One of [ON_TRUE, ON_TRUE_ONE_SHOT, ON_FALSE, ON_FALSE_ONE_SHOT, ON_TOGGLE] was expected. Got ON_BAR instead."))
                    ]) :-
    ev_connected([C], oro_call(C, registerEvent, ["FACT_CHECKING", "ON_BAR", "[x y z]"], Reply)).
test(error_new_instance_without_variable,
     [ setup(ev_fresh),
       true(Replies == [Error, Error])
     ]) :-
    Error = error("laas.openrobots.ontology.exceptions.InvalidEventDescriptorException",
                  "NEW_INSTANCE events require as first parameter a variable name to bind."),
    ev_connected([C],
                 ( oro_call(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE",
                                               "[?a rdf:type Monkey]"], R1),
                   oro_call(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "",
                                               "[?a rdf:type Monkey]"], R2)
                 )),
    Replies = [R1, R2].
test(error_unknown_class, [ setup(ev_fresh),
                            true(Reply == error("laas.openrobots.ontology.exceptions.EventRegistrationException",
                                                "The class Unicorn does not exists in the ontology. Cannot register the NEW_INSTANCE event!"))
                          ]) :-
    ev_connected([C], oro_call(C, registerEvent, ["NEW_CLASS_INSTANCE", "ON_TRUE",
                                                  "[Unicorn]"], Reply)).
test(error_two_classes, [ setup(ev_fresh),
                          true(Name-Tail == "laas.openrobots.ontology.exceptions.EventRegistrationException"-true)
                        ]) :-
    ev_connected([C], oro_call(C, registerEvent, ["NEW_CLASS_INSTANCE", "ON_TRUE",
                                                  "[Monkey, Animal]"], Reply)),
    (   Reply = error(Name, Message),
        string_concat(_, "Only one class name was expected.", Message)
    ->  Tail = true
    ;   Name = Reply,
        Tail = false
    ).
test(error_bad_pattern, [ setup(ev_fresh),
                          true(Name == "laas.openrobots.ontology.exceptions.EventRegistrationException")
                        ]) :-
    ev_connected([C], oro_call(C, registerEvent, ["FACT_CHECKING", "ON_TRUE",
                                                  "[toto titi]"], Reply)),
    (   Reply = error(Name, _)
    ->  true
    ;   Name = Reply
    ).
test(failed_registration_registers_nothing, [ setup(ev_fresh),
                                              true(Watchers == [])
                                            ]) :-
    ev_connected([C],
                 forall(member(Ps, [ ["FOO", "ON_TRUE", "[x y z]"],
                                     ["NEW_CLASS_INSTANCE", "ON_TRUE", "[Unicorn]"],
                                     ["FACT_CHECKING", "ON_TRUE", "[toto titi]"]
                                   ]),
                        oro_call(C, registerEvent, Ps, _))),
    oro_watchers(myself, Watchers).

%   Deduplication.

test(same_watcher_same_id, [ setup(ev_fresh),
                             true(Ids == [U, U, U, U])
                           ]) :-
    ev_connected([A, B],
                 ( ev_register(A, ["NEW_INSTANCE", "ON_TRUE", "a", "[?a rdf:type Monkey]"], U),
                   ev_register(A, ["NEW_INSTANCE", "ON_TRUE", "a", "[?a rdf:type Monkey]"], U2),
                   ev_register(B, ["new_instance", "on_true", "?a", "[?a rdf:type Monkey]"], U3),
                   ev_register(B, ["NEW_INSTANCE", "ON_TRUE", " a ", "[ ?a rdf:type Monkey ]"], U4)
                 )),
    Ids = [U, U2, U3, U4].
test(different_watchers_different_ids, [ setup(ev_fresh),
                                         true(Distinct == 5)
                                       ]) :-
    ev_connected([A],
                 ( ev_register(A, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U1),
                   ev_register(A, ["FACT_CHECKING", "ON_FALSE", "[chicken has teeth]"], U2),
                   ev_register(A, ["FACT_CHECKING", "ON_TRUE",
                                   "[chicken has teeth, chicken has wings]"], U3),
                   ev_register(A, ["FACT_CHECKING", "ON_TRUE",
                                   "[chicken has wings, chicken has teeth]"], U4),
                   ev_register(A, ["NEW_CLASS_INSTANCE", "ON_TRUE", "[Monkey]"], U5)
                 )),
    sort([U1, U2, U3, U4, U5], Ids),
    length(Ids, Distinct).
test(dedup_one_event_per_connection, [ setup(ev_fresh),
                                       true(Got == [[U-""], [U-""]])
                                     ]) :-
    ev_connected([A, B, C],
                 ( ev_register(A, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U),
                   ev_register(A, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], _),
                   ev_register(B, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], _),
                   ev_sentinel(A, S),
                   ev_sentinel(B, S),
                   ev_ok(C, add, ["[chicken has teeth]"]),
                   ev_marker(Statement, Content),
                   ev_ok(C, add, [Statement]),
                   ev_drain(A, S, Content, 200, EA),
                   ev_drain(B, S, Content, 200, EB)
                 )),
    Got = [EA, EB].
test(dedup_subscribers_counted, [ setup(ev_fresh),
                                  true(N == 2)
                                ]) :-
    ev_connected([A, B],
                 ( ev_register(A, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U),
                   ev_register(A, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U),
                   ev_register(B, ["FACT_CHECKING", "ON_TRUE", "[chicken has teeth]"], U),
                   oro_watchers(myself, Watchers),
                   atom_string(Id, U),
                   memberchk(watcher(Id, _, _, _, _, N), Watchers)
                 )).

%   registerEventForAgent: a registry of its own on the robot's model.

test(for_agent_myself, [ setup(ev_fresh),
                         true(Got == [[w-""], [], []]-distinct)
                       ]) :-
    % registerEventForAgent myself: a registry of its own, which
    % clearEvents empties too (ORO-SPEC §7.1: every watcher of the
    % robot's model), as clearEventsForAgent myself does; the sentinel
    % goes with it and is registered again.  A connection has one
    % subscriber for all its registries, so its events keep commit order
    % across them (see commit_order_across_registries).
    ev_connected([A, B],
                 ( ev_ok(A, registerEventForAgent, ["myself", "FACT_CHECKING", "ON_TOGGLE",
                                                    "[chicken has teeth]"], U),
                   ev_register(A, ["FACT_CHECKING", "ON_TOGGLE", "[chicken has teeth]"], P),
                   ev_ok(A, clearEvent, [P]),
                   ev_agent_sentinel(A, S),
                   ev_step(A, B, S, add, ["[chicken has teeth]"], E1),
                   ev_ok(B, clearEvents, []),          % both registries
                   ev_agent_sentinel(A, S1),
                   ev_step(A, B, S1, remove, ["[chicken has teeth]"], E2),
                   ev_ok(A, registerEventForAgent, ["myself", "FACT_CHECKING", "ON_TOGGLE",
                                                    "[chicken has teeth]"], _),
                   ev_ok(B, clearEventsForAgent, ["myself"]),
                   ev_agent_sentinel(A, S2),
                   ev_step(A, B, S2, add, ["[chicken has teeth]"], E3)
                 )),
    maplist(maplist(ev_name_id(U, w)), [E1, E2, E3], Events),
    (   U \== P
    ->  Distinct = distinct
    ;   Distinct = same
    ),
    Got = Events-Distinct.
test(commit_order_across_registries,
     [ setup(ev_fresh),
       true(Bad == [])
     ]) :-
    % A registerEventForAgent watcher fires at each change; the plain
    % sentinel at the next one: its event must come after.
    ev_connected([A, B],
                 ( ev_ok(A, registerEventForAgent, ["myself", "FACT_CHECKING", "ON_TOGGLE",
                                                    "[chicken has teeth]"], U),
                   ev_sentinel(A, S),
                   ev_settle(A, B, S, _),
                   findall(I-Events,
                           ( between(1, 100, I),
                             (   I mod 2 =:= 1
                             ->  Method = add
                             ;   Method = remove
                             ),
                             ev_step(A, B, S, Method, ["[chicken has teeth]"], Events)
                           ), Steps)
                 )),
    exclude(ev_fired_once(U), Steps, Bad).
test(for_agent_unknown, [ setup(ev_fresh),
                          true(Reply == error("laas.openrobots.ontology.exceptions.AgentNotFoundException",
                                              "I couldn't find the agent nobody."))
                        ]) :-
    ev_connected([C], oro_call(C, registerEventForAgent,
                               ["nobody", "FACT_CHECKING", "ON_TRUE", "[a b c]"], Reply)).

:- end_tests(events_registration).

ev_fired_once(Id, _-Events) :-
    Events == [Id-""].

ev_check(Goal, X, Result) :-
    (   call(Goal, X)
    ->  Result = true
    ;   Result = false(X)
    ).

                 /*******************************
                 *     SEED SESSION (§13.13)    *
                 *******************************/

:- begin_tests(events_seed_session,
               [ setup(ev_start_commonsense),
                 cleanup(ev_stop)
               ]).

%   The telnet session verbatim, on one connection, every message read
%   in arrival order: each `ok` comes before the event its request
%   caused, and nothing else is sent (the sentinel, registered first,
%   fires last).

test(telnet_session, [ setup(ev_fresh),
                       true(Got == Expected)
                     ]) :-
    ev_connected([C],
                 ( ev_sentinel(C, S),
                   ev_exchange(C, add, ["[kitchen_table rdf:type Table, fork1 rdf:type Fork, glass1 rdf:type Glass]"], 1, M1),
                   ev_exchange(C, add, ["[fork1 isOn kitchen_table]"], 1, M2),
                   ev_exchange(C, find, ["o", "[?o isAt kitchen_table]"], 1, M3),
                   ev_exchange(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o",
                                                  "[?o isAt kitchen_table, ?o rdf:type Artifact]"], 1, M4),
                   ev_exchange(C, add, ["[Fork rdfs:subClassOf Tableware,Glass rdfs:subClassOf Tableware]"], 2, M5),
                   ev_exchange(C, add, ["[glass1 isOn kitchen_table]"], 2, M6),
                   ev_marker(Statement, Content),
                   ev_exchange(C, add, [Statement], 2, M7)
                 )),
    ev_first_value(M4, Id),
    (   ev_uuid(Id)
    ->  IdShape = uuid
    ;   IdShape = not_a_uuid(Id)
    ),
    (   M3 = [ok(Found)],
        ev_values(Found, Values),
        memberchk("fork1", Values)
    ->  Find = fork1_found
    ;   Find = M3
    ),
    Got = [M1, M2, Find, M4, M5, M6, M7, IdShape],
    Expected = [ [ok("")],
                 [ok("")],
                 fork1_found,
                 [ok(Id)],
                 [ok(""), event(Id, "[\"fork1\"]")],
                 [ok(""), event(Id, "[\"glass1\"]")],
                 [ok(""), event(S, Content)],
                 uuid
               ].
test(two_connections, [ setup(ev_fresh),
                        true(Events == [[], [w-"[\"fork1\"]"], [w-"[\"glass1\"]"], []])
                      ]) :-
    ev_connected([A, B],
                 ( ev_ok(B, add, ["[kitchen_table rdf:type Table, fork1 rdf:type Fork, glass1 rdf:type Glass]"]),
                   ev_register(A, ["NEW_INSTANCE", "ON_TRUE", "o",
                                   "[?o isAt kitchen_table, ?o rdf:type Artifact]"], Id),
                   ev_sentinel(A, S),
                   ev_steps(A, B, S,
                            [ add-["[fork1 isOn kitchen_table]"],
                              add-["[Fork rdfs:subClassOf Tableware,Glass rdfs:subClassOf Tableware]"],
                              add-["[glass1 isOn kitchen_table]"],
                              add-["[glass1 isOn kitchen_table]"]
                            ], Events0)
                 )),
    maplist(maplist(ev_name_id(Id, w)), Events0, Events).

:- end_tests(events_seed_session).


                 /*******************************
                 *            AGENTS            *
                 *******************************/

:- begin_tests(events_agents,
               [ setup(ev_start_commonsense),
                 cleanup(ev_stop)
               ]).

%   §13.11: a watcher on an agent's model sees that model only.  The
%   sentinel sits in the same (agent) registry, on the robot's model.

test(agent_model_events, [ setup(ev_fresh),
                           true(Events == [[], [w-""], [], []])
                         ]) :-
    ev_connected([A, B],
                 ( ev_ok(B, add, ["[gerard rdf:type Agent]"]),
                   ev_ok(A, registerEventForAgent, ["gerard", "FACT_CHECKING", "ON_TRUE",
                                                    "[chicken has teeth]"], U),
                   ev_agent_sentinel(A, S),
                   ev_step(A, B, S, add, ["[chicken has teeth]"], E1),
                   ev_step(A, B, S, addForAgent, ["gerard", "[chicken has teeth]"], E2),
                   ev_ok(B, clearEventsForAgent, ["gerard"]),
                   ev_step(A, B, S, removeForAgent, ["gerard", "[chicken has teeth]"], E3),
                   ev_step(A, B, S, addForAgent, ["gerard", "[chicken has teeth]"], E4)
                 )),
    maplist(maplist(ev_name_id(U, w)), [E1, E2, E3, E4], Events).

:- end_tests(events_agents).

                 /*******************************
                 *          DISCONNECT          *
                 *******************************/

:- begin_tests(events_disconnect,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

ev_watcher_ids(Ids) :-
    oro_watchers(myself, Watchers),
    findall(Id, member(watcher(Id, _, _, _, _, _), Watchers), Ids).

ev_no_watcher(U) :-
    atom_string(Id, U),
    ev_watcher_ids(Ids),
    \+ memberchk(Id, Ids).

ev_subscribers(U, N) :-
    atom_string(Id, U),
    oro_watchers(myself, Watchers),
    memberchk(watcher(Id, _, _, _, _, N), Watchers).

ev_teeth_watcher(["FACT_CHECKING", "ON_TOGGLE", "[chicken has teeth]"]).

test(orphan_watcher_dropped, [ setup(ev_fresh),
                               true(Got == [ok, ok, ok, dropped, new_id, [[], [w-""]]])
                             ]) :-
    ev_teeth_watcher(W),
    test_server_port(Port),
    oro_connect(Port, A),
    ev_register(A, W, Ua),
    oro_disconnect(A),
    ev_connected([B, C],
                 ( % changes right away, racing with the server seeing A leave
                   oro_call(B, add, ["[chicken has teeth]"], R1),
                   oro_call(B, remove, ["[chicken has teeth]"], R2),
                   oro_call(B, add, ["[chicken has teeth]"], R3),
                   (   test_wait_until(ev_no_watcher(Ua), 10)
                   ->  Dropped = dropped
                   ;   Dropped = still_there
                   ),
                   ev_register(C, W, Uc),
                   ev_sentinel(C, S),
                   ev_steps(C, B, S, [ remove-["[chicken has teeth]"],
                                        add-["[chicken has teeth]"]
                                      ], Events0)
                 )),
    maplist(ev_reply_kind, [R1, R2, R3], Kinds),
    (   Uc \== Ua
    ->  NewId = new_id
    ;   NewId = same_id
    ),
    maplist(maplist(ev_name_id(Uc, w)), Events0, Events),
    append(Kinds, [Dropped, NewId, Events], Got).
test(close_method_drops_watchers, [ setup(ev_fresh),
                                    true(Got == [closing, dropped])
                                  ]) :-
    ev_teeth_watcher(W),
    ev_connected([A],
                 ( ev_register(A, W, Ua),
                   oro_call(A, close, [], Closing)
                 )),
    (   test_wait_until(ev_no_watcher(Ua), 10)
    ->  Dropped = dropped
    ;   Dropped = still_there
    ),
    Got = [Closing, Dropped].
test(shared_watcher_survives, [ setup(ev_fresh),
                                true(Got == [1, [[w-""]], same_id])
                              ]) :-
    ev_teeth_watcher(W),
    test_server_port(Port),
    oro_connect(Port, A),
    ev_connected([B, C],
                 ( ev_register(A, W, U),
                   ev_register(B, W, U),
                   ev_sentinel(B, S),
                   oro_disconnect(A),
                   (   test_wait_until(ev_subscribers(U, 1), 10)
                   ->  N = 1
                   ;   ev_subscribers(U, N)
                   ),
                   ev_steps(B, C, S, [add-["[chicken has teeth]"]], Events0),
                   ev_register(C, W, U2)
                 )),
    maplist(maplist(ev_name_id(U, w)), Events0, Events),
    (   U2 == U
    ->  Same = same_id
    ;   Same = new_id
    ),
    Got = [N, Events, Same].
test(disconnected_client_gets_nothing_others_do,
     [ setup(ev_fresh),
       true(Got == [[[w-"[\"coco\"]"]], 0])
     ]) :-
    % Many events for a client that has gone: the server keeps serving.
    test_server_port(Port),
    oro_connect(Port, A),
    ev_register(A, ["NEW_INSTANCE", "ON_TOGGLE", "a", "[?a rdf:type Monkey]"], U),
    oro_disconnect(A),
    ev_connected([B, C],
                 ( forall(between(1, 20, _),
                          ( ev_ok(C, add, ["[coco rdf:type Monkey]"]),
                            ev_ok(C, remove, ["[coco rdf:type Monkey]"])
                          )),
                   ignore(test_wait_until(ev_no_watcher(U), 10)),
                   ev_register(B, ["NEW_INSTANCE", "ON_TOGGLE", "a", "[?a rdf:type Monkey]"], U2),
                   ev_sentinel(B, S),
                   ev_steps(B, C, S, [add-["[coco rdf:type Monkey]"]], Events0)
                 )),
    maplist(maplist(ev_name_id(U2, w)), Events0, Events),
    (   test_wait_until(ev_watcher_ids([]), 10)
    ->  Left = 0
    ;   ev_watcher_ids(Ids),
        length(Ids, Left)
    ),
    Got = [Events, Left].
test(overflow_disconnects_a_client_that_never_reads,
     [ setup(ev_fresh),
       cleanup(( restore_setting(oro_server:event_queue),
                 restore_setting(oro_server:write_timeout)
               )),
       true(Got == [served, dropped, ended, closed, [[w-""]]])
     ]) :-
    ev_overflow_queue(Max),
    set_setting(oro_server:event_queue, Max),
    set_setting(oro_server:write_timeout, 60),
    ev_connected([Other],
                 ( ev_register(Other, ["FACT_CHECKING", "ON_TOGGLE",
                                       "[chicken has teeth]"], W),
                   ev_sentinel(Other, S),
                   ev_threads(Before),
                   ev_connected([Silent],
                                ( ev_register(Silent, ["NEW_INSTANCE", "ON_TOGGLE", "x",
                                                       "[?x ev_big_p ev_big_o]"], U),
                                  ev_threads(After),
                                  subtract(After, Before, Threads),
                                  ev_big_load(Other, 1, ev_no_watcher(U), Served),
                                  (   ev_no_watcher(U)
                                  ->  Dropped = dropped
                                  ;   Dropped = still_there
                                  ),
                                  % Its event delivery thread ends with
                                  % nothing read from it (its connection's
                                  % worker was waiting before it came) ...
                                  (   Threads \== [],
                                      test_wait_until(ev_threads_ended(Threads), 10)
                                  ->  Ended = ended
                                  ;   Ended = running(Threads)
                                  ),
                                  % ... and it reads the end of the connection.
                                  oro_drain(Silent, Messages, 10),
                                  (   last(Messages, end_of_file)
                                  ->  Closed = closed
                                  ;   Closed = open
                                  )
                                )),
                   ev_steps(Other, Other, S, [add-["[chicken has teeth]"]],
                            Events0)
                 )),
    maplist(maplist(ev_name_id(W, w)), Events0, Events),
    Got = [Served, Dropped, Ended, Closed, Events].

:- end_tests(events_disconnect).

ev_reply_kind(ok(_), ok) :- !.
ev_reply_kind(Reply, Reply).

%   A client that registers an event and never reads.  The events are
%   large (50 values of 4,000 characters: 200 KB), so that a few dozen
%   fill the socket's buffers (11 rounds in a trial); then its
%   subscriber's queue fills, past oro_server:event_queue (lowered to 4)
%   it overflows, and the client must be disconnected at once: its
%   delivery thread must end within 10 s with nothing read from it, while
%   write_timeout is 60 s.  The other client makes the changes until the
%   watcher is dropped (at most ev_big_rounds/1 rounds, each an add and
%   a remove of a batch: 80 MB of events), then must still be served and
%   receive its own events.

ev_overflow_queue(4).
ev_big_rounds(200).

%   ev_threads(-Threads): the running threads without an alias: the
%   server's connection workers and event delivery threads among them.

ev_threads(Threads) :-
    findall(T, ( thread_property(T, status(running)),
                 \+ thread_property(T, alias(_))
               ), Threads).

ev_threads_ended(Threads) :-
    \+ ( member(T, Threads),
         catch(thread_property(T, status(running)), _, fail)
       ).

ev_big_batch(Round, Set) :-
    length(Xs, 4000),
    maplist(=(x), Xs),
    atomic_list_concat(Xs, Long),
    findall(S, ( between(1, 50, K),
                 format(string(S), "ev_big_~d_~d_~w ev_big_p ev_big_o",
                        [Round, K, Long])
               ), Ss),
    test_set_text(Ss, Set).

%   ev_big_load(+Conn, +Round, :Done, -Outcome): rounds until Done
%   holds; Outcome is `served`, not_served(Round, Replies) or
%   not_done(Rounds).

:- meta_predicate ev_big_load(+, +, 0, -).

ev_big_load(Conn, Round, Done, Outcome) :-
    ev_big_rounds(Max),
    (   call(Done)
    ->  Outcome = served
    ;   Round > Max
    ->  Outcome = not_done(Max)
    ;   ev_big_batch(Round, Set),
        oro_call(Conn, add, [Set], Added, 10),
        oro_call(Conn, remove, [Set], Removed, 10),
        (   Added-Removed == ok("")-ok("")
        ->  Next is Round + 1,
            ev_big_load(Conn, Next, Done, Outcome)
        ;   Outcome = not_served(Round, Added-Removed)
        )
    ).

                 /*******************************
                 *          PROLOG API          *
                 *******************************/

%   In process, no server: callbacks send ev(Tag, Id, Content) to a
%   message queue.

ev_init_testsuite :-
    ev_stop,
    test_store_testsuite.

ev_to_queue(Queue, Tag, Id, Content) :-
    thread_send_message(Queue, ev(Tag, Id, Content)).

ev_get(Queue, Message) :-
    (   thread_get_message(Queue, Message0, [timeout(5)])
    ->  Message = Message0
    ;   Message = timeout
    ).

%   ev_with_queue(-Queue, -Ids, :Goal): Goal with a new queue; every
%   watcher id Goal adds to the open list Ids is unsubscribed after.

:- meta_predicate ev_with_queue(-, ?, 0).

ev_with_queue(Queue, Ids, Goal) :-
    setup_call_cleanup(
        message_queue_create(Queue),
        once(Goal),
        ( ev_close_list(Ids, Closed),
          forall(member(Id, Closed), catch(oro_unsubscribe(Id), _, true)),
          message_queue_destroy(Queue)
        )).

ev_close_list(List, Closed) :-
    (   var(List)
    ->  Closed = []
    ;   List = [H|T]
    ->  Closed = [H|Closed1],
        ev_close_list(T, Closed1)
    ;   Closed = []
    ).

ev_iri(Name, IRI) :-
    rdf_global_id(oro:Name, IRI).

:- begin_tests(events_prolog_api,
               [ setup(ev_init_testsuite),
                 cleanup(oro_reset)
               ]).

test(subscribe_new_instance, [ setup(oro_reset),
                               true(Message == ev(t, Id, [Coco]))
                             ]) :-
    ev_iri(coco, Coco),
    ev_with_queue(Q, [Id|_],
                  ( oro_subscribe(myself, 'NEW_INSTANCE', 'ON_TRUE', x,
                                  ["?x rdf:type Monkey"], ev_to_queue(Q, t), Id),
                    oro_add(myself, ["coco rdf:type Monkey"]),
                    ev_get(Q, Message)
                  )).
test(subscribe_fact_checking, [ setup(oro_reset),
                                true(Messages == [ev(t, Id, []), ev(t, Id, [])])
                              ]) :-
    ev_with_queue(Q, [Id|_],
                  ( oro_subscribe(myself, fact_checking, on_toggle, '',
                                  ["chicken has teeth"], ev_to_queue(Q, t), Id),
                    oro_add(myself, ["chicken has teeth"]),
                    ev_get(Q, M1),
                    oro_remove(myself, ["chicken has teeth"]),
                    ev_get(Q, M2)
                  )),
    Messages = [M1, M2].
test(subscribe_term_patterns, [ setup(oro_reset),
                                true(Message == ev(t, Id, [Coco]))
                              ]) :-
    ev_iri(coco, Coco),
    ev_with_queue(Q, [Id|_],
                  ( oro_subscribe(myself, new_class_instance, on_true, '',
                                  [oro:'Monkey'], ev_to_queue(Q, t), Id),
                    oro_add(myself, [rdf(oro:coco, rdf:type, oro:'Monkey')]),
                    ev_get(Q, Message)
                  )).
test(subscribe_term_variable, [ setup(oro_reset),
                                 true(Message == ev(t, Id, [Coco]))
                               ]) :-
    ev_iri(coco, Coco),
    ev_with_queue(Q, [Id|_],
                  ( oro_subscribe(myself, new_instance, on_true, X,
                                  [rdf(X, rdf:type, oro:'Monkey')],
                                  ev_to_queue(Q, t), Id),
                    oro_add(myself, ["coco rdf:type Monkey"]),
                    ev_get(Q, Message)
                  )).
test(term_patterns_variants_only,           % not joined by unification
     [ setup(oro_reset),
       true(Got == [two, ev(any, A, []), ev(m, M, [M1])])
     ]) :-
    ev_iri(ev_m1, M1),
    ev_with_queue(Q, [A, T, M|_],
                  ( oro_subscribe(myself, fact_checking, on_true, '',
                                  [rdf(chicken, has, _)],
                                  ev_to_queue(Q, any), A),
                    oro_subscribe(myself, fact_checking, on_true, '',
                                  [rdf(chicken, has, teeth)],
                                  ev_to_queue(Q, teeth), T),
                    oro_subscribe(myself, new_instance, on_true, m,
                                  ["?m rdf:type EvMarker"], ev_to_queue(Q, m), M),
                    (   A == T
                    ->  Two = one
                    ;   Two = two
                    ),
                    oro_add(myself, ["chicken has feathers"]),
                    ev_get(Q, First),
                    oro_add(myself, ["ev_m1 rdf:type EvMarker"]),
                    ev_get(Q, Next)
                  )),
    Got = [Two, First, Next].
test(callback_not_callable, [ setup(oro_reset),
                              error(type_error(callable, 12))
                            ]) :-
    oro_subscribe(myself, fact_checking, on_true, '',
                  ["chicken has teeth"], 12, _).
test(callback_unbound, [ setup(oro_reset),
                         error(instantiation_error)
                       ]) :-
    oro_subscribe(myself, fact_checking, on_true, '',
                  ["chicken has teeth"], _, _).
test(deliver_unbound, error(instantiation_error)) :-
    oro_subscriber_create(_, _, []).
test(watchers, [ setup(oro_reset),
                 true(Got == [ watcher(F, fact_checking, on_true, '', ["chicken has teeth"], 1),
                               watcher(N, new_instance, on_toggle, x, ["?x rdf:type Monkey"], 1)
                             ])
               ]) :-
    ev_with_queue(Q, [F, N|_],
                  ( oro_subscribe(myself, 'FACT_CHECKING', 'ON_TRUE', ignored,
                                  ["chicken has teeth"], ev_to_queue(Q, f), F),
                    oro_subscribe(myself, new_instance, on_toggle, '?x',
                                  ["?x rdf:type Monkey"], ev_to_queue(Q, n), N),
                    oro_watchers(myself, Watchers),
                    include(ev_watcher_in([F, N]), Watchers, Got)
                  )).
test(unsubscribe, [ setup(oro_reset),
                    true(Got == [absent, ev(s, S, [M1])])
                  ]) :-
    ev_iri(ev_m1, M1),
    ev_with_queue(Q, [Id, S|_],
                  ( oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, w), Id),
                    oro_subscribe(myself, new_instance, on_true, m,
                                  ["?m rdf:type EvMarker"], ev_to_queue(Q, s), S),
                    oro_unsubscribe(Id),
                    oro_watchers(myself, Watchers),
                    (   memberchk(watcher(Id, _, _, _, _, _), Watchers)
                    ->  Present = present
                    ;   Present = absent
                    ),
                    oro_add(myself, ["chicken has teeth"]),
                    oro_add(myself, ["ev_m1 rdf:type EvMarker"]),
                    ev_get(Q, Next)
                  )),
    Got = [Present, Next].
test(failing_watcher_dropped_alone,
     [ setup(( oro_reset,
               setting(oro_query:time_limit, Limit0),
               set_setting(oro_query:time_limit, 0.2) )),
       cleanup(set_setting(oro_query:time_limit, Limit0)),
       true(Got == [absent, ev(s, S, [M1])])
     ]) :-
    % The first watcher joins three patterns on one predicate, an
    % EvLink (none at registration): over 3,000 triples its query runs
    % over any time limit, and raises.
    ev_iri(ev_m1, M1),
    findall(St, ( between(1, 3000, I),
                  format(string(St), "evn~d evp evn~d", [I, I])
                ), Chain0),
    Chain = ["evp rdf:type EvLink"|Chain0],
    ev_with_queue(Q, [J, S|_],
                  ( oro_subscribe(myself, new_instance, on_true, x,
                                  ["?x ?p ?y", "?z ?p ?w", "?u ?p ?v",
                                   "?p rdf:type EvLink"],
                                  ev_to_queue(Q, j), J),
                    oro_subscribe(myself, new_instance, on_true, m,
                                  ["?m rdf:type EvMarker"], ev_to_queue(Q, s), S),
                    oro_add(myself, Chain),
                    oro_add(myself, ["ev_m1 rdf:type EvMarker", "evm evp evq"]),
                    ev_get(Q, Next),
                    oro_watchers(myself, Watchers),
                    (   memberchk(watcher(J, _, _, _, _, _), Watchers)
                    ->  Present = present
                    ;   Present = absent
                    )
                  )),
    Got = [Present, Next].
test(dedup_two_callbacks, [ setup(oro_reset),
                            true(Got == [Id, 2, [ev(a, Id, []), ev(b, Id, [])]])
                          ]) :-
    ev_with_queue(Q, [Id, Id2|_],
                  ( oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, a), Id),
                    oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, b), Id2),
                    oro_watchers(myself, Watchers),
                    memberchk(watcher(Id, _, _, _, _, N), Watchers),
                    oro_add(myself, ["chicken has teeth"]),
                    ev_get(Q, M1),
                    ev_get(Q, M2)
                  )),
    msort([M1, M2], Ms),
    Got = [Id2, N, Ms].
test(unsubscribe_shared_watcher,
     [ setup(oro_reset),
       true(Got == [Id, present(1), [ev(b, Id, []), ev(s, S, [M1])]])
     ]) :-
    % Planners A and B subscribe to identical watchers (one id); A
    % unsubscribes with its own handle and B goes on.  A cannot fire
    % later: oro_unsubscribe/1 returns once its thread has ended.
    ev_iri(ev_m1, M1),
    ev_with_queue(Q, [SubA, SubB, S|_],
                  ( oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, a),
                                  SubA, []),
                    oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, b),
                                  SubB, []),
                    oro_subscribe(myself, new_instance, on_true, m,
                                  ["?m rdf:type EvMarker"], ev_to_queue(Q, s), S),
                    SubA = oro_subscription(Id, _),
                    SubB = oro_subscription(IdB, _),
                    oro_unsubscribe(SubA),
                    oro_unsubscribe(SubA),                  % nothing: stopped
                    oro_watchers(myself, Watchers),
                    (   memberchk(watcher(Id, _, _, _, _, N), Watchers)
                    ->  Present = present(N)
                    ;   Present = absent
                    ),
                    oro_add(myself, ["chicken has teeth"]),
                    oro_add(myself, ["ev_m1 rdf:type EvMarker"]),
                    ev_get(Q, M1st),                        % two threads:
                    ev_get(Q, M2nd)                         % any order
                  )),
    msort([M1st, M2nd], Next),
    Got = [IdB, Present, Next].
test(unsubscribe_id_stops_every_callback,
     [ setup(oro_reset),
       true(Got == [Id, absent])
     ]) :-
    ev_with_queue(Q, [SubA, SubB|_],
                  ( oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, a),
                                  SubA, []),
                    oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, b),
                                  SubB, []),
                    SubA = oro_subscription(Id, _),
                    SubB = oro_subscription(IdB, _),
                    oro_unsubscribe(Id),
                    oro_watchers(myself, Watchers),
                    (   memberchk(watcher(Id, _, _, _, _, _), Watchers)
                    ->  Present = present
                    ;   Present = absent
                    )
                  )),
    Got = [IdB, Present].
test(reset_destroys_callback_subscribers,
     [ setup(oro_reset),
       true(Got == [3, ended, 0, 0, []])
     ]) :-
    ev_threads(Before),
    ev_with_queue(Q, [Sub|_],
                  ( oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, a),
                                  Sub, [max_queue(5)]),
                    oro_subscribe(myself, fact_checking, on_true, '',
                                  ["chicken has teeth"], ev_to_queue(Q, b), _),
                    oro_subscribe(myself, new_instance, on_true, x,
                                  ["?x rdf:type Monkey"], ev_to_queue(Q, c), _),
                    ev_threads(After),
                    subtract(After, Before, Threads),
                    length(Threads, NThreads),
                    oro_reset,                      % no wait after it
                    (   ev_threads_ended(Threads)
                    ->  Ended = ended
                    ;   Ended = running
                    ),
                    aggregate_all(count, oro_events_delivery:callback_subscriber(_, _),
                                  NCallbacks),
                    aggregate_all(count, oro_events_delivery:subscriber(_, _, _, callback),
                                  NSubscribers),
                    oro_unsubscribe(Sub),           % nothing: destroyed
                    oro_add(myself, ["chicken has teeth", "coco rdf:type Monkey"]),
                    oro_events_sync,
                    ev_drain_queue(Q, Late)
                  )),
    Got = [NThreads, Ended, NCallbacks, NSubscribers, Late].
test(overflow_tells_the_planner,
     [ setup(oro_reset),
       true(Got == [told, ended, absent, 0, 0])
     ]) :-
    % The callback blocks on Gate, the queue holds one firing: of three
    % firings the third overflows at the latest.
    message_queue_create(Gate),
    ev_threads(Before),
    call_cleanup(
        ev_with_queue(Q, [Sub|_],
                      ( oro_subscribe(myself, new_instance, on_true, x,
                                      ["?x rdf:type Monkey"],
                                      ev_gated(Gate, Q), Sub,
                                      [ max_queue(1),
                                        on_overflow(ev_overflowed(Q))
                                      ]),
                        Sub = oro_subscription(Id, _),
                        ev_threads(After),
                        subtract(After, Before, Threads),
                        forall(member(M, [m1, m2, m3]),
                               ( format(string(St), "~w rdf:type Monkey", [M]),
                                 oro_add(myself, [St])
                               )),
                        (   thread_get_message(Q, overflowed(Told), [timeout(5)])
                        ->  (   Told == Sub
                            ->  Tell = told
                            ;   Tell = told(Told)
                            )
                        ;   Tell = not_told
                        ),
                        forall(between(1, 3, _), thread_send_message(Gate, go)),
                        (   test_wait_until(ev_threads_ended(Threads), 5)
                        ->  Ended = ended
                        ;   Ended = running
                        ),
                        oro_events_sync,
                        oro_watchers(myself, Watchers),
                        (   memberchk(watcher(Id, _, _, _, _, _), Watchers)
                        ->  Present = present
                        ;   Present = absent
                        ),
                        aggregate_all(count, oro_events_delivery:callback_subscriber(_, _),
                                      NCallbacks),
                        aggregate_all(count, oro_events_delivery:subscriber(_, _, _, callback),
                                      NSubscribers)
                      )),
        message_queue_destroy(Gate)),
    Got = [Tell, Ended, Present, NCallbacks, NSubscribers].
test(one_shot_removed_after_sync, [ setup(oro_reset),
                                    true(Got == [ev(t, Id, [Coco]), absent])
                                  ]) :-
    ev_iri(coco, Coco),
    ev_with_queue(Q, [Id|_],
                  ( oro_subscribe(myself, new_instance, on_true_one_shot, x,
                                  ["?x rdf:type Monkey"], ev_to_queue(Q, t), Id),
                    oro_add(myself, ["coco rdf:type Monkey"]),
                    oro_events_sync,
                    oro_watchers(myself, Watchers),
                    (   memberchk(watcher(Id, _, _, _, _, _), Watchers)
                    ->  Present = present
                    ;   Present = absent
                    ),
                    ev_get(Q, Message)
                  )),
    Got = [Message, Present].
test(bad_type, [ setup(oro_reset),
                 error(domain_error(oro_event_type, foo))
               ]) :-
    ev_with_queue(Q, _,
                  oro_subscribe(myself, foo, on_true, '', ["a b c"],
                                ev_to_queue(Q, t), _)).
test(bad_trigger, [ setup(oro_reset),
                    error(domain_error(oro_event_trigger, sometimes))
                  ]) :-
    ev_with_queue(Q, _,
                  oro_subscribe(myself, fact_checking, sometimes, '', ["a b c"],
                                ev_to_queue(Q, t), _)).
test(unknown_model, [ setup(oro_reset),
                      error(existence_error(agent, nobody))
                    ]) :-
    ev_with_queue(Q, _,
                  oro_subscribe(nobody, fact_checking, on_true, '', ["a b c"],
                                ev_to_queue(Q, t), _)).
:- end_tests(events_prolog_api).

ev_watcher_in(Ids, watcher(Id, _, _, _, _, _)) :-
    memberchk(Id, Ids).

%   ev_gated(+Gate, +Queue, +Id, +Content): a callback that waits for
%   `go` on Gate (5 s at most) before passing the firing on.

ev_gated(Gate, Queue, Id, Content) :-
    ignore(thread_get_message(Gate, go, [timeout(5)])),
    thread_send_message(Queue, ev(gated, Id, Content)).

ev_overflowed(Queue, Subscription) :-
    thread_send_message(Queue, overflowed(Subscription)).

%   ev_drain_queue(+Queue, -Messages): what Queue holds now.

ev_drain_queue(Queue, Messages) :-
    (   thread_get_message(Queue, M, [timeout(0)])
    ->  Messages = [M|Rest],
        ev_drain_queue(Queue, Rest)
    ;   Messages = []
    ).

                 /*******************************
                 *            STRESS            *
                 *******************************/

%   N clients, each making M changes that toggle its own K facts
%   `cK_I state on` (one batch add or remove per change); one listener
%   connection registers, for every fact, three FACT_CHECKING watchers
%   in this order: ON_TOGGLE, ON_TRUE, ON_FALSE.  Since a subscriber
%   receives the firings of a change in registration order and changes
%   in commit order, the listener's events restricted to one fact are
%   exactly [toggle, true, toggle, false, ...], M pairs.  Meanwhile the
%   listener sends requests of its own: replies and events share its
%   socket and must never mix.

ev_stress_params(4, 50, 5).                     % N, M, K

ev_stress(Result) :-
    ev_stress_params(N, M, K),
    ev_connected([L], ev_stress_run(L, N, M, K, Result)).

ev_stress_run(L, N, M, K, stress(Statuses, Count, BadFacts, Extra, BadReplies)) :-
    test_server_port(Port),
    findall(I-J, ( between(1, N, I), between(1, K, J) ), Facts),
    maplist(ev_stress_register(L), Facts, Watchers),
    ev_sentinel(L, S),
    message_queue_create(Done),
    call_cleanup(
        ( findall(T, ( between(1, N, I),
                       thread_create(ev_stress_client(Port, I, M, K, Done), T, [])
                     ), Threads),
          Total is N * K * 2 * M,
          ev_stress_collect(L, Total, Events, BadReplies),
          length(Events, Count),
          ev_stress_join(Done, Threads, Statuses),
          ev_settle(L, L, S, Extra)
        ),
        message_queue_destroy(Done)),
    ev_stress_expected(M, Expected),
    include(ev_stress_bad(Events, Expected), Watchers, Bad),
    maplist(ev_stress_fact, Bad, BadFacts).

ev_stress_register(L, I-J, w(I, J, Tg, T, F)) :-
    format(string(P), "[c~d_~d state on]", [J, I]),
    ev_register(L, ["FACT_CHECKING", "ON_TOGGLE", P], Tg),
    ev_register(L, ["FACT_CHECKING", "ON_TRUE", P], T),
    ev_register(L, ["FACT_CHECKING", "ON_FALSE", P], F).

ev_stress_fact(w(I, J, _, _, _), I-J).

ev_stress_statements(I, K, Text) :-
    findall(S, ( between(1, K, J),
                 format(string(S), "c~d_~d state on", [J, I])
               ), Ss),
    test_set_text(Ss, Text).

ev_stress_client(Port, I, M, K, Done) :-
    ev_stress_statements(I, K, Text),
    catch(setup_call_cleanup(
              oro_connect(Port, C),
              ev_stress_changes(C, 1, M, Text, Status),
              oro_disconnect(C)),
          E,
          Status = exception(E)),
    thread_send_message(Done, done(I, Status)).

ev_stress_changes(C, J, M, Text, Status) :-
    (   J > M
    ->  Status = ok
    ;   (   J mod 2 =:= 1
        ->  Method = add
        ;   Method = remove
        ),
        oro_call(C, Method, [Text], Reply, 10),
        (   Reply = ok(_)
        ->  J1 is J + 1,
            ev_stress_changes(C, J1, M, Text, Status)
        ;   Status = failed(J, Reply)
        )
    ).

%   ev_stress_collect(+L, +Total, -Events, -BadReplies): read Total
%   events (Id-Content), fewer if one does not come within 10 s.  Every
%   50 events the listener also sends a request, whose reply comes
%   among the events: BadReplies are the replies that are not a
%   boolean `ok`.

ev_stress_collect(_, 0, [], []) :-
    !.
ev_stress_collect(L, N, Events, BadReplies) :-
    (   N mod 50 =:= 0
    ->  oro_call(L, check, ["[c1_1 state on]"], Reply, 10),
        (   memberchk(Reply, [ok("true"), ok("false")])
        ->  BadReplies = BadReplies1
        ;   BadReplies = [Reply|BadReplies1]
        )
    ;   BadReplies = BadReplies1
    ),
    oro_next_event(L, Event, 10),
    (   Event = event(Id, Content)
    ->  Events = [Id-Content|Rest],
        N1 is N - 1,
        ev_stress_collect(L, N1, Rest, BadReplies1)
    ;   Events = [],
        BadReplies1 = []
    ).

%   ev_stress_join(+Done, +Threads, -Statuses): the clients' statuses,
%   sorted by client; a client that does not finish within 60 s is
%   reported as `timeout` and stopped.

ev_stress_join(Done, Threads, Statuses) :-
    length(Threads, N),
    ev_stress_done(Done, N, Pairs0),
    keysort(Pairs0, Pairs),
    pairs_values(Pairs, Statuses0),
    (   length(Statuses0, N)
    ->  Statuses = Statuses0
    ;   Statuses = [timeout|Statuses0],
        forall(member(T, Threads),
               catch(thread_signal(T, throw(ev_stress_timeout)), _, true))
    ),
    forall(member(T, Threads), thread_join(T, _)).

ev_stress_done(_, 0, []) :-
    !.
ev_stress_done(Done, N, Pairs) :-
    (   thread_get_message(Done, done(I, Status), [timeout(60)])
    ->  Pairs = [I-Status|Rest],
        N1 is N - 1,
        ev_stress_done(Done, N1, Rest)
    ;   Pairs = []
    ).

ev_stress_expected(M, Expected) :-
    findall(Kinds, ( between(1, M, J),
                     (   J mod 2 =:= 1
                     ->  Kinds = [toggle-"", true-""]
                     ;   Kinds = [toggle-"", false-""]
                     )
                   ), Nested),
    append(Nested, Expected).

ev_stress_bad(Events, Expected, w(_, _, Tg, T, F)) :-
    findall(Kind-C, ( member(Id-C, Events),
                      ev_stress_kind(Id, Tg, T, F, Kind)
                    ), Got),
    Got \== Expected.

ev_stress_kind(Id, Tg, T, F, Kind) :-
    (   Id == Tg
    ->  Kind = toggle
    ;   Id == T
    ->  Kind = true
    ;   Id == F
    ->  Kind = false
    ).

:- begin_tests(events_stress,
               [ setup(ev_start_testsuite),
                 cleanup(ev_stop)
               ]).

test(toggles_from_four_clients, [ setup(ev_fresh),
                                  true(Result == stress([ok, ok, ok, ok], 2000, [], [], []))
                                ]) :-
    ev_stress(Result).
test(toggles_while_others_subscribe_and_unsubscribe,
     [ setup(ev_fresh),
       true(Got == stress([ok, ok, ok, ok], 2000, [], [], [])-
                   stable(2000, [], [])-
                   churn(true, true))
     ]) :-
    ev_stress_params(N, M, K),
    ev_connected([L], ev_churn_run(L, N, M, K, Got)).

:- end_tests(events_stress).

%   The same with churn: while the N clients write, a socket client
%   keeps connecting, registering the listener's watchers of a random
%   fact (so it shares their ids) and one of its own, clearing its own
%   and disconnecting; and a Prolog thread keeps subscribing to one of
%   them with oro_subscribe/8 and unsubscribing with its handle.  Two
%   stable subscribers must still receive exact logs: the listener
%   connection, and an in-process subscriber (oro_subscriber_create/3,
%   one queue for all its watchers) registered on the same watchers
%   before the writers start.  Its log is complete when destroying it
%   returns (what it queued is delivered first), so that any extra
%   event is seen.  Each churn worker reports ok(Cycles, Shared), the
%   cycles where it got the listener's ids; both must have made a cycle
%   while the writers ran, every one on the shared watchers.

ev_churn_run(L, N, M, K, Stress-stable(PCount, PBad, PExtra)-churn(SocketOk, PrologOk)) :-
    test_server_port(Port),
    findall(I-J, ( between(1, N, I), between(1, K, J) ), Facts),
    maplist(ev_stress_register(L), Facts, Watchers),
    ev_sentinel(L, S),
    Total is N * K * 2 * M,
    message_queue_create(PQ),
    message_queue_create(Done),
    message_queue_create(Stop),
    oro_subscriber_create(ev_to_queue(PQ, p), PSub, []),
    call_cleanup(
        ( maplist(ev_churn_stable(PSub), Watchers),
          thread_create(ev_churn_socket(Port, Watchers, Stop, 0, 0, SStatus0),
                        ST, []),
          thread_create(ev_churn_prolog(Watchers, Stop, 0, 0, PStatus0),
                        PT, []),
          ev_churn_started(Stop),
          findall(T, ( between(1, N, I),
                       thread_create(ev_stress_client(Port, I, M, K, Done), T, [])
                     ), Threads),
          ev_stress_collect(L, Total, Events, BadReplies),
          length(Events, Count),
          ev_stress_join(Done, Threads, Statuses),
          ev_settle(L, L, S, Extra),
          thread_send_message(Stop, stop),
          thread_join(ST, SExit),
          thread_join(PT, PExit),
          ev_churn_collect(PQ, Total, PEvents),
          oro_subscriber_destroy(PSub),
          ev_drain_queue(PQ, PExtra)
        ),
        ( oro_subscriber_destroy(PSub),
          maplist(message_queue_destroy, [PQ, Done, Stop])
        )),
    ignore(SStatus0 = unbound),
    ignore(PStatus0 = unbound),
    ev_stress_expected(M, Expected),
    include(ev_stress_bad(Events, Expected), Watchers, Bad),
    maplist(ev_stress_fact, Bad, BadFacts),
    Stress = stress(Statuses, Count, BadFacts, Extra, BadReplies),
    length(PEvents, PCount),
    include(ev_stress_bad(PEvents, Expected), Watchers, PBadW),
    maplist(ev_stress_fact, PBadW, PBad),
    debug(oro(test_events), 'Churn: socket ~q, prolog ~q', [SExit, PExit]),
    ev_churn_ok(SExit, SocketOk),
    ev_churn_ok(PExit, PrologOk).

%   The churn threads report through their exit status.

ev_churn_ok(exited(ok(Cycles, Shared)), Ok) :-
    Cycles > 0,
    Shared =:= Cycles,
    !,
    Ok = true.
ev_churn_ok(Exit, Exit).

ev_churn_stable(PSub, w(I, J, Tg, T, F)) :-
    format(string(P), "c~d_~d state on", [J, I]),
    forall(member(Trigger-Id, ["ON_TOGGLE"-Tg, "ON_TRUE"-T, "ON_FALSE"-F]),
           ( oro_register_event(myself, "FACT_CHECKING", Trigger, '', [P],
                                PSub, Id0),
             atom_string(Id0, Id)               % the listener's watcher
           )).

%   ev_churn_started(+Stop): wait (5 s at most) until both churn
%   workers have made a cycle, so that they run while the writers do.

ev_churn_started(Stop) :-
    ignore(test_wait_until(( thread_peek_message(Stop, cycle(socket)),
                             thread_peek_message(Stop, cycle(prolog))
                           ), 5)).

ev_churn_stopped(Stop) :-
    thread_peek_message(Stop, stop).

ev_churn_socket(Port, Watchers, Stop, Cycles, Shared, _) :-
    (   ev_churn_stopped(Stop)
    ->  thread_exit(ok(Cycles, Shared))
    ;   random_member(w(I, J, Tg, T, F), Watchers),
        format(string(P), "[c~d_~d state on]", [J, I]),
        format(string(Own), "[c~d_~d state on, churn_~d is busy]", [J, I, Cycles]),
        setup_call_cleanup(
            oro_connect(Port, C),
            ( ev_register(C, ["FACT_CHECKING", "ON_TOGGLE", P], Tg1),
              ev_register(C, ["FACT_CHECKING", "ON_TRUE", P], T1),
              ev_register(C, ["FACT_CHECKING", "ON_FALSE", P], F1),
              ev_register(C, ["FACT_CHECKING", "ON_TOGGLE", Own], O),
              ev_ok(C, clearEvent, [O])
            ),
            oro_disconnect(C)),
        (   [Tg1, T1, F1] == [Tg, T, F]
        ->  Shared1 is Shared + 1
        ;   Shared1 = Shared
        ),
        ev_churn_note(Stop, socket),
        Cycles1 is Cycles + 1,
        ev_churn_socket(Port, Watchers, Stop, Cycles1, Shared1, _)
    ).

ev_churn_prolog(Watchers, Stop, Cycles, Shared, _) :-
    (   ev_churn_stopped(Stop)
    ->  thread_exit(ok(Cycles, Shared))
    ;   random_member(w(I, J, Tg, _, _), Watchers),
        format(string(P), "c~d_~d state on", [J, I]),
        oro_subscribe(myself, "FACT_CHECKING", "ON_TOGGLE", '', [P],
                      ev_ignore, Sub, []),
        oro_unsubscribe(Sub),
        (   Sub = oro_subscription(Id, _),
            atom_string(Id, Tg)
        ->  Shared1 is Shared + 1
        ;   Shared1 = Shared
        ),
        ev_churn_note(Stop, prolog),
        Cycles1 is Cycles + 1,
        ev_churn_prolog(Watchers, Stop, Cycles1, Shared1, _)
    ).

ev_churn_note(Stop, Worker) :-
    (   thread_peek_message(Stop, cycle(Worker))
    ->  true
    ;   thread_send_message(Stop, cycle(Worker))
    ).

ev_ignore(_, _).

%   ev_churn_collect(+Queue, +N, -Events): N events of the in-process
%   subscriber, fewer if one does not come within 10 s.  They are
%   written as the listener receives them: Id-"" (the ids as strings;
%   FACT_CHECKING firings have no content).

ev_churn_collect(_, 0, []) :-
    !.
ev_churn_collect(Queue, N, Events) :-
    (   thread_get_message(Queue, ev(p, Id0, Content0), [timeout(10)])
    ->  atom_string(Id0, Id),
        (   Content0 == []
        ->  Content = ""
        ;   Content = Content0
        ),
        Events = [Id-Content|Rest],
        N1 is N - 1,
        ev_churn_collect(Queue, N1, Rest)
    ;   Events = []
    ).

                 /*******************************
                 *     INCREMENTAL EVALUATION   *
                 *******************************/

%   Watchers are evaluated from the triples a change adds or removes
%   where that is sound (oro_events module doc).  The guard: random
%   changes on a small world with inferences (sub-classes, a
%   sub-property isOn of isAt, inverses, a symmetric and a transitive
%   property with a sub-property, domain and range, a functional
%   property, literals, facts of the ontology layer removed and put
%   back, owl:sameAs and sub-class axioms added and removed) are made
%   twice from a fresh store, once with incremental evaluation and once
%   with oro_events:incremental set to false, with the same watchers
%   of every type and trigger; both must fire exactly the same events
%   at the same changes.  The changes are drawn from fixed seeds, before
%   either run.

ev_inc_ontology(
"@prefix :     <http://kb.openrobots.org#> .
@prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .
@prefix owl:  <http://www.w3.org/2002/07/owl#> .

:Obj a owl:Class .
:Cup a owl:Class ; rdfs:subClassOf :Obj .
:Mug a owl:Class ; rdfs:subClassOf :Cup .
:Place a owl:Class .
:Table a owl:Class ; rdfs:subClassOf :Place .
:Person a owl:Class .
:isAt a owl:ObjectProperty .
:isOn a owl:ObjectProperty ; rdfs:subPropertyOf :isAt .
:isUnder a owl:ObjectProperty ; owl:inverseOf :isOn .
:isNextTo a owl:ObjectProperty , owl:SymmetricProperty .
:contains a owl:ObjectProperty , owl:TransitiveProperty .
:componentOf a owl:ObjectProperty ; rdfs:subPropertyOf :contains .
:isInside a owl:ObjectProperty ; owl:inverseOf :contains .
:holds a owl:ObjectProperty ; rdfs:domain :Person ; rdfs:range :Obj .
:locatedIn a owl:ObjectProperty , owl:FunctionalProperty ;
    rdfs:subPropertyOf :isAt ; rdfs:range :Place .
:hasAge a owl:DatatypeProperty .
:i1 :isOn :i2 .
:i3 :contains :i4 .
:i5 a :Mug .
").

%   ev_inc_store: a fresh store on that ontology alone.

ev_inc_store :-
    ev_stop,
    ev_inc_ontology(Text),
    setup_call_cleanup(
        tmp_file_stream(File, Out, [extension(ttl), encoding(utf8)]),
        ( write(Out, Text),
          close(Out),
          oro_init([commonsense(false), ontologies([File])])
        ),
        delete_file(File)).

%   ev_with_toggle_watcher(+Patterns, :Goal): run Goal once a
%   NEW_INSTANCE ON_TOGGLE watcher of ?x on Patterns is registered in
%   myself and the watcher thread has nothing pending any more.

:- meta_predicate ev_with_toggle_watcher(+, 0).

ev_with_toggle_watcher(Patterns, Goal) :-
    message_queue_create(Q),
    oro_subscriber_create(ev_to_queue(Q, f), Subscriber, [in_watcher(true)]),
    call_cleanup(
        ( oro_register_event(myself, "NEW_INSTANCE", "ON_TOGGLE", x,
                             Patterns, Subscriber, _),
          oro_events_sync,
          once(Goal)
        ),
        ( oro_subscriber_destroy(Subscriber),
          message_queue_destroy(Q)
        )).

ev_inc_cleanup :-
    set_setting(oro_events:incremental, true),
    set_setting(oro_events:index, true),
    oro_reset.

%   The watchers: Type-Var-Patterns, each registered with every trigger
%   (NEW_CLASS_INSTANCE with those that fire).

ev_inc_watch(new_instance, x, ["?x isOn i1"]).
ev_inc_watch(new_instance, x, ["?x isAt ?y"]).
ev_inc_watch(new_instance, y, ["?x isAt ?y"]).
ev_inc_watch(new_instance, x, ["?x isAt i2"]).
ev_inc_watch(new_instance, x, ["?x rdf:type Cup"]).
ev_inc_watch(new_instance, x, ["?x rdf:type Person"]).
ev_inc_watch(new_instance, y, ["?x isUnder ?y", "?y rdf:type Table"]).
ev_inc_watch(new_instance, x, ["i1 isNextTo ?x"]).
ev_inc_watch(new_instance, x, ["?x isNextTo ?x"]).
ev_inc_watch(new_instance, y, ["?x contains ?y"]).
ev_inc_watch(new_instance, x, ["i3 contains ?x"]).
ev_inc_watch(new_instance, x, ["?x isInside i4"]).
ev_inc_watch(new_instance, z, ["?x holds ?y", "?y isOn ?z"]).
ev_inc_watch(new_instance, c, ["i2 rdf:type ?c"]).
ev_inc_watch(new_instance, x, ["?x rdf:type ?c"]).
ev_inc_watch(new_instance, x, ["?x rdf:type owl:Thing"]).
ev_inc_watch(new_instance, x, ["?x ?p i5"]).
ev_inc_watch(new_instance, y, ["?x owl:sameAs ?y"]).
ev_inc_watch(new_instance, a, ["?x hasAge ?a"]).
ev_inc_watch(new_instance, x, ["?x hasAge 3"]).
ev_inc_watch(new_instance, x, ["?x locatedIn ?y", "?y isNextTo i6"]).
ev_inc_watch(new_instance, v, ["?x isOn ?y"]).
ev_inc_watch(new_class_instance, '', ["Cup"]).
ev_inc_watch(new_class_instance, '', ["Obj"]).
ev_inc_watch(new_class_instance, '', ["Place"]).
ev_inc_watch(fact_checking, '', ["i1 isOn i2"]).
ev_inc_watch(fact_checking, '', ["?x isOn ?y", "?y isOn ?x"]).
ev_inc_watch(fact_checking, '', ["i3 contains i5"]).
ev_inc_watch(fact_checking, '', ["?x rdf:type Person"]).
ev_inc_watch(fact_checking, '', ["i1 isAt ?y", "?y rdf:type Place"]).

ev_inc_triggers(new_class_instance, [on_true, on_true_one_shot, on_toggle]) :- !.
ev_inc_triggers(_, [on_toggle, on_true, on_false, on_true_one_shot,
                    on_false_one_shot]).

%   The reference comparison adds watchers that only hold through
%   schema axioms its changes add (ev_inc_schema/2): an inverse of
%   holds, a range of isAt, a domain of isNextTo, a symmetric holds, a
%   transitive isNextTo.

ev_ref_watch(new_instance, y, ["?x isHeldBy ?y"]).
ev_ref_watch(new_instance, x, ["i1 isHeldBy ?x"]).
ev_ref_watch(new_instance, x, ["?x rdf:type Obj"]).
ev_ref_watch(new_instance, x, ["?x rdf:type Place", "i1 isAt ?x"]).
ev_ref_watch(new_instance, x, ["i2 isNextTo ?x"]).
ev_ref_watch(new_instance, x, ["?x holds i1"]).
ev_ref_watch(new_instance, x, ["?x isOn ?y", "?y isNextTo i5"]).
ev_ref_watch(fact_checking, '', ["i1 isNextTo i3"]).
ev_ref_watch(fact_checking, '', ["i4 isHeldBy i2"]).

%   ev_inc_register(+Subscriber, -Ids): register every watcher (those
%   of ev_inc_watch/3, and with Set `reference` those of
%   ev_ref_watch/3 too); Ids lists their ids in registration order.

ev_inc_register(Subscriber, Ids) :-
    ev_inc_register(base, Subscriber, Ids).

ev_inc_register(Set, Subscriber, Ids) :-
    findall(Type-Trigger-Var-Patterns,
            ( ev_inc_set_watch(Set, Type, Var, Patterns),
              ev_inc_triggers(Type, Triggers),
              member(Trigger, Triggers)
            ), Watchers),
    findall(Id, ( member(Type-Trigger-Var-Patterns, Watchers),
                  oro_register_event(myself, Type, Trigger, Var, Patterns,
                                     Subscriber, Id)
                ), Ids).

ev_inc_set_watch(base, Type, Var, Patterns) :-
    ev_inc_watch(Type, Var, Patterns).
ev_inc_set_watch(reference, Type, Var, Patterns) :-
    (   ev_inc_watch(Type, Var, Patterns)
    ;   ev_ref_watch(Type, Var, Patterns)
    ).
ev_inc_set_watch(classes, Type, Var, Patterns) :-
    ev_cls_watch(Type, Var, Patterns).

%   The watchers of the set `classes`: on rdf:type, only watchers whose
%   triggers are all classes (a type with its subject a variable and
%   its class given), so that the writers decide for each type triple
%   whether to send it (oro_events_monitor:type_filter/3).

ev_cls_watch(new_instance, x, ["?x rdf:type Cup"]).
ev_cls_watch(new_instance, x, ["?x rdf:type Person"]).
ev_cls_watch(new_instance, y, ["?x isUnder ?y", "?y rdf:type Table"]).
ev_cls_watch(new_instance, x, ["?x rdf:type Place", "i1 isAt ?x"]).
ev_cls_watch(new_instance, x, ["?x isOn i1"]).
ev_cls_watch(new_class_instance, '', ["Obj"]).
ev_cls_watch(fact_checking, '', ["?x rdf:type Person"]).
ev_cls_watch(fact_checking, '', ["i1 isAt ?y", "?y rdf:type Place"]).

%   Random changes.  The generator keeps the statements that may be
%   asserted, to remove some of them; it starts from the ontology's
%   facts (removing one masks it).

ev_inc_individual(X) :-
    random_between(1, 6, N),
    format(atom(X), "i~d", [N]).

ev_inc_statement(Set, S) :-
    random_between(1, 12, K),
    ev_inc_individual(X),
    ev_inc_individual(Y),
    (   K =< 3
    ->  random_member(C, ['Cup', 'Mug', 'Obj', 'Table', 'Place', 'Person']),
        format(string(S), "~w rdf:type ~w", [X, C])
    ;   K =< 4
    ->  random_between(2, 4, Age),
        format(string(S), "~w hasAge ~d", [X, Age])
    ;   ev_inc_predicates(Set, Ps),
        random_member(P, Ps),
        format(string(S), "~w ~w ~w", [X, P, Y])
    ).

ev_inc_predicates(base, [isOn, isUnder, isAt, isNextTo, contains,
                         componentOf, isInside, holds, locatedIn]).
ev_inc_predicates(reference, [isOn, isUnder, isAt, isNextTo, contains,
                              componentOf, isInside, holds, locatedIn,
                              isHeldBy]).
ev_inc_predicates(classes, [isOn, isUnder, isAt, holds, locatedIn]).

ev_inc_statements(Set, Min, Max, Ss) :-
    random_between(Min, Max, N),
    length(Ss, N),
    maplist(ev_inc_statement(Set), Ss).

%   ev_inc_schema(+Set, -Axioms): the schema axioms the changes add and
%   remove.  Those of `reference` change every kind of inference the
%   index follows: sub-classes and sub-properties, an inverse, domains
%   and ranges, symmetric and transitive properties (also removing, by
%   masking, axioms of the ontology layer).

ev_inc_schema(base, [ "Mug rdfs:subClassOf Table",
                      "isNextTo rdfs:subPropertyOf isAt",
                      "componentOf rdfs:subPropertyOf isOn"
                    ]).
ev_inc_schema(reference, [ "Mug rdfs:subClassOf Table",
                           "isNextTo rdfs:subPropertyOf isAt",
                           "componentOf rdfs:subPropertyOf isOn",
                           "isHeldBy owl:inverseOf holds",
                           "isAt rdfs:range Place",
                           "isNextTo rdfs:domain Obj",
                           "holds rdfs:range Mug",
                           "holds rdf:type owl:SymmetricProperty",
                           "isNextTo rdf:type owl:TransitiveProperty",
                           "isUnder rdfs:subPropertyOf isNextTo",
                           "isUnder owl:inverseOf isOn",
                           "holds rdfs:domain Person",
                           "isNextTo rdf:type owl:SymmetricProperty",
                           "componentOf rdfs:subPropertyOf contains"
                         ]).
ev_inc_schema(classes, [ "Mug rdfs:subClassOf Table",
                         "Table rdfs:subClassOf Cup",
                         "Person rdfs:subClassOf Place",
                         "holds rdfs:domain Cup",
                         "isAt rdfs:range Place"
                       ]).

ev_inc_pick(Pool, Min, Max, Ss) :-
    random_between(Min, Max, N),
    length(Pool, L),
    (   L =:= 0
    ->  Ss = []
    ;   findall(S, ( between(1, N, _),
                     random_member(S, Pool)
                   ), Ss0),
        sort(Ss0, Ss)
    ).

ev_inc_ops(Seed, N, Ops) :-
    ev_inc_ops(base, Seed, N, Ops).

ev_inc_ops(Set, Seed, N, Ops) :-
    set_random(seed(Seed)),
    ev_inc_ops_(N, Set, ["i1 isOn i2", "i3 contains i4", "i5 rdf:type Mug"],
                Ops).

%   Past 94, a schema axiom is added or removed: 6 % of the changes
%   for `base`, 28 % for `reference`.

ev_inc_range(base, 100).
ev_inc_range(reference, 130).
ev_inc_range(classes, 110).

ev_inc_ops_(0, _, _, []) :-
    !.
ev_inc_ops_(N, Set, Pool0, [Op|Ops]) :-
    ev_inc_range(Set, Range),
    random_between(1, Range, R),
    (   R =< 40
    ->  ev_inc_statements(Set, 1, 3, Ss),
        Op = add(Ss),
        append(Ss, Pool0, Pool)
    ;   R =< 65
    ->  ev_inc_pick(Pool0, 1, 2, Ss),
        Op = remove(Ss),
        subtract(Pool0, Ss, Pool)
    ;   R =< 78
    ->  ev_inc_individual(X),
        ev_inc_individual(Y),
        format(string(S), "~w locatedIn ~w", [X, Y]),
        Op = update([S]),
        Pool = [S|Pool0]
    ;   R =< 84
    ->  ev_inc_pick(Pool0, 1, 1, Rs),
        ev_inc_statements(Set, 1, 2, As),
        Op = update_and_remove(As, Rs),
        subtract(Pool0, Rs, Pool1),
        append(As, Pool1, Pool)
    ;   R =< 88
    ->  random_member(P, ["?x isOn ?y", "?x contains ?y", "?x rdf:type ?c",
                            "i1 ?p ?o"]),
        Op = clear([P]),
        Pool = Pool0
    ;   R =< 94
    ->  ev_inc_individual(X),
        ev_inc_individual(Y),
        format(string(S), "~w owl:sameAs ~w", [X, Y]),
        random_member(Op, [add([S]), remove([S])]),
        Pool = Pool0
    ;   ev_inc_schema(Set, Axioms),
        random_member(S, Axioms),
        random_member(Op, [add([S]), remove([S])]),
        Pool = Pool0
    ),
    N1 is N - 1,
    ev_inc_ops_(N1, Set, Pool, Ops).

ev_inc_apply(add(Ss)) :-
    oro_add(myself, Ss).
ev_inc_apply(remove(Ss)) :-
    oro_remove(myself, Ss).
ev_inc_apply(update(Ss)) :-
    oro_update(myself, Ss).
ev_inc_apply(update_and_remove(As, Rs)) :-
    oro_statements(As, Adds, _),
    oro_statements(Rs, Removes, _),
    oro_store_write(test(myself),
                    ( oro_store_retract(myself, Removes),
                      oro_store_assert(myself, Adds, longterm)
                    )).
ev_inc_apply(clear(Ps)) :-
    oro_clear(myself, Ps).

%   ev_inc_run(+How, +Ops, -Log): from a fresh store, register
%   the watchers (one subscriber, called in the watcher thread, so that
%   every firing of a change is logged once oro_events_sync/0 returns),
%   make the changes, and log Step-WatcherIndex-Content for each
%   firing.  How is one of ev_inc_settings/4: `true` (incremental
%   evaluation), `false` (full evaluation of the watchers the index
%   selects), `reference` (no index, setting oro_events:index false:
%   every watcher, in full, at every change; with the watchers of
%   ev_ref_watch/3 too), `indexed` (those watchers, with the index),
%   `filtered` and `unfiltered` (the class-anchored watchers, with and
%   without the index).

ev_inc_run(How, Ops, Log) :-
    ev_inc_store,
    ev_inc_mode(How, Set),
    message_queue_create(Q),
    oro_subscriber_create(ev_to_queue(Q, f), Subscriber, [in_watcher(true)]),
    call_cleanup(
        ( ev_inc_register(Set, Subscriber, Ids),
          findall(Step-Firings,
                  ( nth1(Step, Ops, Op),
                    ev_inc_apply(Op),
                    oro_events_sync,
                    ev_inc_after(Set),
                    ev_inc_drain(Q, Ids, Firings)
                  ), Log)
        ),
        ( oro_subscriber_destroy(Subscriber),
          message_queue_destroy(Q)
        )).

%   ev_inc_mode(+How, -Set): set oro_events' settings for How; Set
%   names the watchers registered (ev_inc_register/3).

ev_inc_mode(How, Set) :-
    ev_inc_settings(How, Set, Index, Incremental),
    set_setting(oro_events:index, Index),
    set_setting(oro_events:incremental, Incremental).

%   ev_inc_settings(?How, ?Set, ?Index, ?Incremental): the watchers of
%   Set evaluated with the settings index and incremental of oro_events
%   (`indexed`: the reference set, with the index).

ev_inc_settings(true,       base,      true,  true).
ev_inc_settings(false,      base,      true,  false).
ev_inc_settings(indexed,    reference, true,  true).
ev_inc_settings(reference,  reference, false, true).
ev_inc_settings(filtered,   classes,   true,  true).
ev_inc_settings(unfiltered, classes,   false, true).

%   ev_inc_after(+Set): after each change of the set `classes`, a query
%   compiles the shared schema tables of the robot's model (as the
%   server's queries do), so that the writers' filter of type triples
%   is at work from the next change on: left to itself, the first write
%   after a schema change is sent whole and warms the tables for the
%   writes after it.

ev_inc_after(classes) :-
    !,
    once(oro_subclass(myself, oro:'Cup', _)).
ev_inc_after(_).

ev_inc_drain(Q, Ids, Firings) :-
    (   thread_get_message(Q, ev(f, Id, Content), [timeout(0)])
    ->  nth1(I, Ids, Id),
        Firings = [I-Content|Rest],
        ev_inc_drain(Q, Ids, Rest)
    ;   Firings = []
    ).

%   ev_inc_compare(+Seed, +N, -Result): `same(Firings)` (the number of
%   firings) or the first step where the two runs differ.

ev_inc_compare(Seed, N, Result) :-
    ev_inc_ops(Seed, N, Ops),
    ev_inc_run(true, Ops, Incremental),
    ev_inc_run(false, Ops, Full),
    (   Incremental == Full
    ->  aggregate_all(sum(L), ( member(_-Fs, Full), length(Fs, L) ), Count),
        Result = same(Count)
    ;   nth1(Step, Incremental, I),
        nth1(Step, Full, F),
        I \== F
    ->  nth1(Step, Ops, Op),
        Result = differ(Seed, Step, Op, incremental(I), full(F))
    ;   Result = differ(Seed, lengths)
    ).

ev_inc_fires(Seed, N) :-
    ev_inc_compare(Seed, N, Result),
    assertion(Result = same(_)),
    Result = same(Count),
    assertion(Count > 0).

%   ev_set_compare(+Set, +How1, +How2, +Seed, +N, -Result): the same for
%   the changes and watchers of Set, run as How1 and as How2 (see
%   ev_inc_run/3), on changes that also add and remove the axioms of
%   ev_inc_schema(Set, _); Result is same(Firings, SchemaChanges) or
%   the first step where the two runs differ.  The sets: `reference`,
%   the index (with incremental evaluation) against the reference mode,
%   about one change in four a schema axiom; `classes`, the writers
%   filtering type triples against the reference mode, which sends
%   every change and evaluates every watcher in full.

ev_set_compare(Set, How1, How2, Seed, N, Result) :-
    ev_inc_ops(Set, Seed, N, Ops),
    ev_inc_run(How1, Ops, Log1),
    ev_inc_run(How2, Ops, Log2),
    (   Log1 == Log2
    ->  aggregate_all(sum(L), ( member(_-Fs, Log2), length(Fs, L) ), Count),
        aggregate_all(count, ( member(Op, Ops), ev_schema_op(Set, Op) ), Schema),
        Result = same(Count, Schema)
    ;   nth1(Step, Log1, F1),
        nth1(Step, Log2, F2),
        F1 \== F2
    ->  nth1(Step, Ops, Op),
        Result = differ(Seed, Step, Op, How1-F1, How2-F2)
    ;   Result = differ(Seed, lengths)
    ).

ev_schema_op(Set, Op) :-
    (   Op = add([S])
    ;   Op = remove([S])
    ),
    ev_inc_schema(Set, Axioms),
    memberchk(S, Axioms).

ev_set_fires(Set, Seed, N) :-
    ev_set_modes(Set, How1, How2),
    ev_set_compare(Set, How1, How2, Seed, N, Result),
    assertion(Result = same(_, _)),
    Result = same(Count, Schema),
    assertion(Count > 0),
    assertion(Schema > 0).

ev_set_modes(reference, indexed, reference).
ev_set_modes(classes, filtered, unfiltered).

:- begin_tests(events_incremental,
               [ cleanup(ev_inc_cleanup)
               ]).

test(random_changes_seed_1) :-
    ev_inc_fires(1, 40).
test(random_changes_seed_2) :-
    ev_inc_fires(2, 40).
test(random_changes_seed_3) :-
    ev_inc_fires(3, 40).
test(random_changes_seed_4) :-
    ev_inc_fires(4, 40).

%   The dependency index checked by the reference mode.

test(index_against_reference_seed_11) :-
    ev_set_fires(reference, 11, 60).
test(index_against_reference_seed_12) :-
    ev_set_fires(reference, 12, 60).
test(index_against_reference_seed_13) :-
    ev_set_fires(reference, 13, 60).
test(index_against_reference_seed_14) :-
    ev_set_fires(reference, 14, 60).

:- end_tests(events_incremental).

%   The writers' filter of type triples (oro_events_monitor:type_filter/3): a
%   type triple is sent to the watcher thread only if its class is under
%   a class some watcher is anchored by, when every watcher on rdf:type
%   is anchored by classes.

:- begin_tests(events_type_filter,
               [ cleanup(ev_inc_cleanup)
               ]).

%   ev_cls_followed(-Followed): how the writers follow rdf:type in the
%   robot's model now, once the shared schema is compiled.

ev_cls_followed(Followed) :-
    oro_events_sync,
    once(oro_subclass(myself, oro:'Cup', _)),
    rdf_equal(rdf:type, Type),
    oro_events_monitor:pair_followed(myself, Type, Followed).

ev_cls_register(Subscriber, Patterns) :-
    oro_register_event(myself, new_instance, on_true, x, Patterns,
                       Subscriber, _).

test(filter_only_with_class_anchors,
     [ true(Followed1-Followed2 = classes(_)-true)
     ]) :-
    ev_inc_store,
    oro_subscriber_create(ev_to_queue(_, f), Subscriber, [in_watcher(true)]),
    call_cleanup(
        ( ev_cls_register(Subscriber, ["?x rdf:type Cup"]),
          ev_cls_followed(Followed1),
          ev_cls_register(Subscriber, ["i2 rdf:type ?c"]),
          ev_cls_followed(Followed2)
        ),
        oro_subscriber_destroy(Subscriber)).
test(type_triple_sent_by_its_class,
     [ true(Sent == [true, false, true, false])
     ]) :-
    ev_inc_store,
    oro_subscriber_create(ev_to_queue(_, f), Subscriber, [in_watcher(true)]),
    call_cleanup(
        ( ev_cls_register(Subscriber, ["?x rdf:type Cup"]),
          ev_cls_followed(classes(Key)),
          findall(F, ( member(Sign-Class, [add-'Mug', add-'Place',
                                           update-'Place', del-'Obj']),
                       rdf_global_id(oro:Class, C),
                       oro_events_monitor:triple_followed(classes(Key), myself, Sign,
                                                  C, F)
                     ), Sent)
        ),
        ( nb_setval(oro_events_followed_type, false),
          oro_subscriber_destroy(Subscriber)
        )).
test(new_agent_class) :-
    ev_stop,
    oro_init([]),
    oro_add(myself, ["Droid rdfs:subClassOf Human"]),
    ev_cls_followed(Followed),
    assertion(Followed = classes(_)),
    oro_add(myself, ["r2d2 rdf:type Droid", "cup9 rdf:type Cup"]),
    oro_agents(Agents),
    assertion(memberchk(r2d2, Agents)),
    assertion(\+ memberchk(cup9, Agents)).

test(filter_back_after_schema_change) :-
    ev_stop,
    oro_init([]),
    oro_add(myself, ["human1 rdf:type Human"]),   % its model: a schema change
    oro_events_sync,
    oro_add(myself, ["cup1 rdf:type Cup"]),       % asks for the schema
    rdf_equal(rdf:type, Type),
    test_wait_until(oro_events_monitor:pair_followed(myself, Type, classes(_)), 10).

test(random_changes_against_reference,
     [ forall(member(Seed, [21, 22, 23]))
     ]) :-
    ev_set_fires(classes, Seed, 60).

:- end_tests(events_type_filter).

%   ev_inc_session(+Watchers, +Ops, -Log): from a fresh store on the
%   small world, register Watchers (Type-Trigger-Var-Patterns), apply
%   Ops (as ev_inc_apply/1 takes them, or bulk(N, Statement) to add N
%   statements and Statement in one change), and log, for each change,
%   the firings as WatcherIndex-Names (local names of the values).

ev_inc_session(Watchers, Ops, Log) :-
    ev_inc_store,
    message_queue_create(Q),
    oro_subscriber_create(ev_to_queue(Q, f), Subscriber, [in_watcher(true)]),
    call_cleanup(
        ( findall(Id, ( member(Type-Trigger-Var-Patterns, Watchers),
                        oro_register_event(myself, Type, Trigger, Var, Patterns,
                                           Subscriber, Id)
                      ), Ids),
          findall(Firings,
                  ( member(Op, Ops),
                    ev_inc_session_apply(Op),
                    oro_events_sync,
                    ev_inc_drain(Q, Ids, Firings0),
                    maplist(ev_inc_names, Firings0, Firings)
                  ), Log)
        ),
        ( oro_subscriber_destroy(Subscriber),
          message_queue_destroy(Q)
        )).

ev_inc_session_apply(bulk(N, Statement)) :-
    !,
    findall(S, ( between(1, N, I),
                 format(string(S), "bulk_~d isNextTo i6", [I])
               ), Ss),
    oro_add(myself, [Statement|Ss]).
ev_inc_session_apply(Op) :-
    ev_inc_apply(Op).

ev_inc_names(I-Content, I-Names) :-
    maplist(ev_inc_name, Content, Names).

ev_inc_name(IRI, Name) :-
    (   rdf_global_id(oro:Name0, IRI)
    ->  Name = Name0
    ;   Name = IRI
    ).

:- begin_tests(events_incremental_cases,
               [ cleanup(ev_inc_cleanup)
               ]).

test(one_of_many_anchored_watchers,
     [ true(Log == [[150-[c1]], [], [150-[c1]]])
     ]) :-
    findall(new_instance-on_toggle-x-[P],
            ( between(1, 200, K),
              format(string(P), "?x isOn table_~d", [K])
            ), Watchers),
    ev_inc_session(Watchers,
                   [ add(["c1 isOn table_150"]),
                     add(["c1 isOn table_1500", "c2 isNextTo table_150"]),
                     remove(["c1 isOn table_150"])
                   ], Log).
test(through_inverse_and_sub_property,
     [ true(Log == [[1-[c1], 2-[c1]], [], [1-[c1]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["?x isOn t1"],
                     new_instance-on_toggle-x-["?x isAt t1"]
                   ],
                   [ add(["t1 isUnder c1"]),
                     add(["c1 isAt t1"]),           % isAt now holds twice
                     remove(["t1 isUnder c1"])      % isAt still holds, isOn not
                   ], Log).
test(watched_among_unwatched_predicates,
     [ true(Log == [[1-[c1]], [], [1-[c2]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["?x isAt t1"] ],
                   [ add(["c1 hasColor red", "c1 isOn t1", "c2 hasColor blue"]),
                     add(["c2 hasColor green", "c3 isVisible true"]),
                     add(["c3 hasColor red", "t1 isUnder c2"])
                   ], Log).
%   What a change records for the watcher thread: only the triples of
%   predicates some watcher depends on (the store's agents watcher
%   follows rdf:type), each model and predicate touched once (whatever
%   the graph of the model), and no owl:sameAs table while the model has
%   no such individuals.

test(delta_of_followed_predicates_only,
     [ true(Delta-Touched == [d(myself, add, C1, IsOn, T1)]-
                             [myself-HasColor, myself-IsOn])
     ]) :-
    ev_inc_store,
    rdf_global_id(oro:c1, C1),
    rdf_global_id(oro:isOn, IsOn),
    rdf_global_id(oro:t1, T1),
    rdf_global_id(oro:hasColor, HasColor),
    ev_with_toggle_watcher(
        ["?x isOn t1"],
        ( oro_graph(myself, profile(longterm), Long),
          oro_graph(myself, mask, Mask),
          setup_call_cleanup(
              nb_setval(oro_events_in_commit, true),
              ( oro_events_monitor:note(Long, C1, HasColor, literal(red), add),
                oro_events_monitor:note(Long, C1, IsOn, T1, add),
                oro_events_monitor:note(Long, C1, HasColor, literal(blue), add),
                oro_events_monitor:note(Mask, C1, HasColor, literal(red), add)
              ),
              nb_setval(oro_events_in_commit, false)),
          oro_events_monitor:take_touched(Touched, _, _),
          oro_events_monitor:take_delta(Delta)
        )).
%   What touch/5 works out for a pair holds for one transaction only:
%   one that is rolled back leaves nothing noted for the next (rdf_db
%   calls the monitor only for what it commits).

test(rolled_back_change_notes_nothing,
     [ true(Touched-Delta == []-[])
     ]) :-
    ev_inc_store,
    rdf_global_id(oro:c1, C1),
    rdf_global_id(oro:isOn, IsOn),
    rdf_global_id(oro:t1, T1),
    ev_with_toggle_watcher(
        ["?x isOn t1"],
        ( \+ oro_store_write(test,
                             ( oro_store_assert(myself, [rdf(C1, IsOn, T1)],
                                                longterm),
                               fail
                             )),
          oro_events_monitor:take_touched(Touched, _, _),
          oro_events_monitor:take_delta(Delta)
        )).
test(same_as_table_only_with_same_individuals,
     [ true(Result == before(false, [])-after(true))
     ]) :-
    ev_inc_store,
    rdf_global_id(oro:c1, C1),
    rdf_global_id(oro:isOn, IsOn),
    rdf_global_id(oro:t1, T1),
    Delta = [d(myself, add, C1, IsOn, T1)],
    oro_events_eval:model_delta(myself, Delta, _, _, Same),
    assoc_to_list(Same, Pairs0),
    (   oro_reason:oro_has_same_individuals(myself)
    ->  Has0 = true
    ;   Has0 = false
    ),
    oro_add(myself, ["t2 owl:sameAs t1"]),
    (   oro_reason:oro_has_same_individuals(myself)
    ->  Has1 = true
    ;   Has1 = false
    ),
    Result = before(Has0, Pairs0)-after(Has1).
test(same_as_individuals,
     [ true(Log == [[], [1-[c1]], [1-[c1]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["?x isOn t1"] ],
                   [ add(["t2 owl:sameAs t1"]),
                     add(["c1 isOn t2"]),
                     remove(["c1 isOn t2"])
                   ], Log).
test(transitive_chain,
     [ true(Log == [[1-[c7]], [1-[c8]], [1-[c7, c8]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["i3 contains ?x"] ],
                   [ add(["i4 contains c7"]),         % i3 contains i4 (ontology)
                     add(["c7 componentOf c8"]),      % a sub-property
                     remove(["i4 contains c7"])
                   ], Log).
test(ontology_fact_removed_and_back,
     [ true(Log == [[1-[i1]], [1-[i1], 2-[]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["?x isOn i2"],
                     fact_checking-on_toggle-''-["i1 isAt i2"]
                   ],
                   [ remove(["i1 isOn i2"]),       % the fact starts unknown (false)
                     add(["i1 isOn i2"])
                   ], Log).
test(type_by_class_and_by_range,
     [ true(Log == [[1-[c1], 2-[c1]], [2-[c2]], [1-[c1]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["?x rdf:type Cup"],
                     new_class_instance-on_true-''-["Obj"]
                   ],
                   [ add(["c1 rdf:type Mug"]),
                     add(["p1 holds c2"]),             % range Obj
                     remove(["c1 rdf:type Mug"])
                   ], Log).
test(large_change_evaluated_in_full,
     [ true(Log == [[1-[big], 2-[i6]], [1-[big]]])
     ]) :-
    ev_inc_session([ new_instance-on_toggle-x-["?x isOn t9"],
                     new_instance-on_toggle-x-["bulk_1200 isNextTo ?x"]
                   ],
                   [ bulk(1200, "big isOn t9"),
                     clear(["?x isOn t9"])
                   ], Log).

test(literal_replaced_by_an_equal_one_of_another_type,
     [ true(Log == [[1-[Three]], [1-[Three], 1-[ThreeD]], [1-[ThreeD]]])
     ]) :-
    % 3 and 3.0 are two values of ?a, as a full evaluation finds them,
    % though each matches the other in a pattern: 3 is lost when only
    % 3.0 is left.
    test_literal(xsd:int, '3', Three),
    test_literal(xsd:double, '3.0', ThreeD),
    ev_inc_session([ new_instance-on_toggle-a-["i1 hasAge ?a"] ],
                   [ add(["i1 hasAge 3"]),
                     update_and_remove(["i1 hasAge 3.0"], ["i1 hasAge 3"]),
                     update_and_remove([], ["i1 hasAge 3.0"])
                   ], Log).
:- end_tests(events_incremental_cases).

%   A watcher following a predicate makes the events monitor note each
%   triple of it a write adds: that leaves no clause behind for the
%   clause garbage collector either (see the monitor's comment).

:- begin_tests(events_clause_churn,
               [ setup(ev_init_testsuite),
                 cleanup(oro_reset)
               ]).

test(followed_adds_retract_no_clause, [ setup(oro_reset),
                                        true(Reclaimed < 20)
                                      ]) :-
    message_queue_create(Queue),
    oro_subscribe(myself, new_instance, on_true, x, ["?x isOn place_1"],
                  ev_to_queue(Queue, t), _),
    test_churn_adds(warm, _),
    test_churn_adds(probe, Reclaimed),
    assertion(ev_get(Queue, ev(t, _, _))),
    message_queue_destroy(Queue).

%   Watchers registered and dropped leave retracted clauses in the
%   watcher thread's tables; the thread reclaims them, so that lookups
%   (the monitor's, for every triple written) do not step over them.

test(dropped_watchers_reclaimed, [ setup(oro_reset),
                                   true(Left < Peak / 4)
                                 ]) :-
    oro_events_sync,
    ev_watcher_tables_size(Before),
    message_queue_create(Queue),
    oro_subscriber_create(ev_to_queue(Queue, t), Subscriber, []),
    forall(between(1, 100, K),
           ( format(string(Pattern), "?o isOn place_~d", [K]),
             oro_register_event(myself, new_instance, on_true, o, [Pattern],
                                Subscriber, _)
           )),
    oro_events_sync,
    ev_watcher_tables_size(Registered),
    oro_clear_events(myself),
    oro_events_sync,
    ev_watcher_tables_size(After),
    oro_subscriber_destroy(Subscriber),
    message_queue_destroy(Queue),
    Peak is Registered - Before,
    Left is After - Before.

%   The monitor asks whether anything is watched from a counter the
%   watcher thread keeps: it must agree with the watchers at every step,
%   whatever removes them.

test(watcher_count_agrees, [ setup(oro_reset),
                             true(Counts == [3, 3, 2, 1, 0])
                           ]) :-
    message_queue_create(Queue),
    oro_subscriber_create(ev_to_queue(Queue, t), Subscriber, []),
    oro_events_sync,
    ev_watcher_clauses(Base),             % the agents' internal ones
    ev_register_on_true(Subscriber, "?o isOn place_1", Id1),
    ev_register_on_true(Subscriber, "?o isOn place_1", Id1),    % shared
    ev_register_on_true(Subscriber, "?o isOn place_2", _),
    oro_register_event(myself, fact_checking, on_true_one_shot, '',
                       ["count_probe isOn place_3"], Subscriber, _),
    ev_counted(Base, C1),
    oro_events_sync,
    ev_counted(Base, C2),
    oro_add(myself, ["count_probe isOn place_3"]),  % fires, then dropped
    assertion(ev_get(Queue, ev(t, _, _))),
    oro_events_sync,
    ev_counted(Base, C3),
    oro_clear_event(myself, Id1),
    oro_events_sync,
    ev_counted(Base, C4),
    oro_clear_events(myself),
    oro_events_sync,
    ev_counted(Base, C5),
    oro_reset,
    ev_watcher_count(Flag),
    ev_watcher_clauses(C6),
    assertion(Flag == C6),
    oro_subscriber_destroy(Subscriber),
    message_queue_destroy(Queue),
    Counts = [C1, C2, C3, C4, C5].

:- end_tests(events_clause_churn).

ev_watcher_tables_size(Size) :-
    aggregate_all(sum(S),
                  ( member(Head, [ watcher(_, _, _, _, _),
                                   watcher_trigger(_, _, _, _, _),
                                   watcher_dep(_, _, _)
                                 ]),
                    predicate_property(oro_events_registry:Head, size(S))
                  ),
                  Size).

ev_register_on_true(Subscriber, Pattern, Id) :-
    oro_register_event(myself, new_instance, on_true, o, [Pattern],
                       Subscriber, Id).

ev_watcher_count(N) :-
    flag(oro_events_watchers, N, N).

%   ev_watcher_clauses(-N): the watchers there are, as watcher/5 holds
%   them; ev_counted(+Base, -N): those beyond Base, after checking that
%   the counter agrees with the clauses.

ev_watcher_clauses(N) :-
    aggregate_all(count, oro_events_registry:watcher(_, _, _, _, _), N).

ev_counted(Base, N) :-
    ev_watcher_count(Flag),
    ev_watcher_clauses(All),
    assertion(Flag == All),
    N is All - Base.

                 /*******************************
                 *     SCHEMA TABLES AHEAD      *
                 *******************************/

%   When idle, the watcher thread compiles the shared schema tables of
%   the models that have none for the current schema generation, so the
%   first query after a schema change (or on a new agent's model) does
%   not; also after a change that sends no message of triples (a
%   rolled-back write, an ontology loaded, a store rebuilt).  The
%   tables are observed with oro_compiled_schema/2, which never
%   compiles; no query runs on the model meanwhile.  With the setting
%   off, the same changes leave the tables to the first query (the
%   control: nothing else compiles them).

:- begin_tests(events_schema_ahead,
               [ setup(ev_init_testsuite),
                 cleanup(( set_setting(oro_events:warm_schemas, true),
                           oro_reset
                         ))
               ]).

test(after_schema_change, [ setup(ev_warm_reset(true)),
                            true(Key1 \== Key0)
                          ]) :-
    ev_warm_key(myself, Key0),
    oro_add(myself, ["Gadget rdfs:subClassOf Artifact"]),
    ev_warm_key(myself, Key1).
test(new_agent_model, [ setup(ev_warm_reset(true)) ]) :-
    oro_add(myself, ["gerard rdf:type Agent"]),
    oro_agents(Agents),
    assertion(memberchk(gerard, Agents)),
    ev_warm_key(gerard, _),
    ev_warm_key(myself, _).
test(after_rolled_back_schema_write, [ setup(ev_warm_reset(true)),
                                       true(Key1 \== Key0)
                                     ]) :-
    ev_warm_key(myself, Key0),
    oro_statements(["Gadget rdfs:subClassOf Artifact"], Triples, _),
    catch(oro_store_write(test(myself),
                          ( oro_store_assert(myself, Triples, longterm),
                            throw(ev_rolled_back)
                          )),
          ev_rolled_back, true),
    ev_warm_key(myself, Key1),             % before any query compiles them
    assertion(\+ oro_check(myself, ["Gadget rdfs:subClassOf Artifact"])).
test(after_ontology_load, [ setup(ev_warm_reset(true)),
                            true(Key1 \== Key0)
                          ]) :-
    ev_warm_key(myself, Key0),
    test_fixture('store_kitchen.nt', File),
    oro_load_ontology(File),
    ev_warm_key(myself, Key1).
test(after_store_rebuild, [ setup(ev_warm_reset(true)),
                            true(Key1 \== Key0)
                          ]) :-
    ev_warm_key(myself, Key0),
    oro_store_rebuild,
    ev_warm_key(myself, Key1).
%   Another thread compiles the shared tables of the generation a
%   write's schema triple has bumped, before the write commits: they
%   lack the triple, and the writing thread must not use them.

test(writer_not_given_others_tables, [ setup(ev_warm_reset(true)),
                                       true(Seen-Key == true-Key0)
                                     ]) :-
    oro_statements(["Gadget rdfs:subClassOf Artifact",
                    "g1 rdf:type Gadget"], Triples, _),
    oro_store_write(test(myself),
                    ( oro_store_assert(myself, Triples, longterm),
                      thread_self(Me),
                      thread_create(( oro_shared_schema(myself, K),
                                      thread_send_message(Me, ev_key(K))
                                    ), T, []),
                      thread_join(T, true),
                      thread_get_message(ev_key(Key0)),
                      oro_compiled_schema(myself, Key),
                      test_bool(oro_check(myself, ["g1 rdf:type Artifact"]),
                                Seen)
                    )).
test(off_leaves_them_to_the_query, [ setup(ev_warm_reset(false)) ]) :-
    oro_add(myself, ["Gadget rdfs:subClassOf Artifact"]),
    oro_events_sync,
    assertion(\+ oro_compiled_schema(myself, _)),
    assertion(\+ oro_check(myself, ["thing_1 rdf:type Gadget"])),  % a query
    assertion(oro_compiled_schema(myself, _)).

:- end_tests(events_schema_ahead).

%   ev_warm_reset(+Warm): a reset store with the setting warm_schemas
%   Warm, once the watcher thread has done what the reset gave it.

ev_warm_reset(Warm) :-
    set_setting(oro_events:warm_schemas, Warm),
    oro_reset,
    oro_events_sync.

%   ev_warm_key(+Model, -Key): Model's shared tables for the current
%   generation, once the watcher thread has compiled them (10 s at
%   most).

ev_warm_key(Model, Key) :-
    assertion(test_wait_until(oro_compiled_schema(Model, _), 10)),
    oro_compiled_schema(Model, Key).

                 /*******************************
                 *         MANY WATCHERS        *
                 *******************************/

%   Registering, joining, clearing and dispatching cost the watcher
%   thread the same work (its inferences, counted by
%   thread_statistics/3, no clock) with 2,000 watchers as with 100: no
%   step looks at every watcher.  Joining an identical watcher once
%   compared the new one with each watcher of the model in turn (two
%   inferences a watcher), and a change of a transitive property (isOn
%   is one in the test ontology) evaluated every watcher of a pattern
%   through it (214,000 inferences with 100, 5 million with 2,100).
%   The work is counted from one
%   oro_events_sync/0 to the next, so that it includes what the thread
%   does after answering.

:- begin_tests(events_many_watchers,
               [ setup(ev_init_testsuite),
                 cleanup(oro_reset)
               ]).

test(work_independent_of_watchers,
     [ setup(oro_reset),
       true(Growth == [0, 0, 0, 0])
     ]) :-
    message_queue_create(Queue),
    oro_subscriber_create(ev_to_queue(Queue, t), Subscriber, []),
    ev_register_many(Subscriber, 1, 100),
    ev_watcher_steps(Subscriber, Queue, 101, Few),
    ev_register_many(Subscriber, 102, 2100),
    ev_watcher_steps(Subscriber, Queue, 2101, Many),
    oro_subscriber_destroy(Subscriber),
    message_queue_destroy(Queue),
    maplist(ev_work_growth, Few, Many, Growth).

:- end_tests(events_many_watchers).

ev_register_many(Subscriber, From, To) :-
    forall(between(From, To, K),
           ( format(string(Pattern), "?o isOn many_~d", [K]),
             ev_register_on_true(Subscriber, Pattern, _)
           )).

%   ev_watcher_steps(+Subscriber, +Queue, +K, -Works): the watcher
%   thread's work to register watcher K (new), to register it again
%   (joined), to process a change firing it, and to clear it.

ev_watcher_steps(Subscriber, Queue, K, [New, Join, Change, Clear]) :-
    format(string(Pattern), "?o isOn many_~d", [K]),
    format(string(Fact), "many_obj_~d isOn many_~d", [K, K]),
    ev_watcher_work(ev_register_on_true(Subscriber, Pattern, Id), New),
    ev_watcher_work(ev_register_on_true(Subscriber, Pattern, Id), Join),
    ev_watcher_work(oro_add(myself, [Fact]), Change),
    assertion(ev_get(Queue, ev(t, Id, _))),
    ev_watcher_work(oro_clear_event(myself, Id), Clear).

ev_watcher_work(Goal, Work) :-
    oro_events_sync,
    thread_statistics(oro_watcher, inferences, I0),
    call(Goal),
    oro_events_sync,
    thread_statistics(oro_watcher, inferences, I1),
    Work is I1 - I0.

%   ev_work_growth(+Few, +Many, -Growth): 0 when the work with many
%   watchers is within a few inferences of the work with few (the
%   thread may compile a schema table ahead, or collect clauses, in
%   one of them), else the work in both.

ev_work_growth(Few, Many, Growth) :-
    (   Many =< Few + 200
    ->  Growth = 0
    ;   Growth = Few-Many
    ).
