#include "scanfilter/dds/dds_participant.hpp"

#include <stdexcept>

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>

namespace scanfilter::dds_io {

using namespace eprosima::fastdds::dds;

DdsParticipant::DdsParticipant(const ParticipantSettings& settings) {
  DomainParticipantFactory* factory = DomainParticipantFactory::get_instance();
  if (settings.profiles_file.empty())
    throw std::runtime_error("no Fast DDS profiles file given (dds.profiles_file)");
  if (factory->load_XML_profiles_file(settings.profiles_file) != ReturnCode_t::RETCODE_OK)
    throw std::runtime_error(settings.profiles_file + ": cannot load Fast DDS XML profiles");
  DomainParticipantQos qos;
  if (factory->get_participant_qos_from_profile(settings.profile, qos) != ReturnCode_t::RETCODE_OK)
    throw std::runtime_error(settings.profiles_file + ": no participant profile '" + settings.profile + "'");
  applyDiscovery(settings.discovery, qos);
  qos.name(settings.name);
  applySecurity(settings.security, qos);  // last: it checks the discovery setup it must not be combined with
  participant_ = factory->create_participant(static_cast<DomainId_t>(settings.domain_id), qos);
  if (participant_ == nullptr) throw std::runtime_error("cannot create a DDS participant on domain " +
                                                        std::to_string(settings.domain_id) +
                                                        securityFailureHint(settings.security));
  publisher_ = participant_->create_publisher(PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
  if (publisher_ == nullptr || subscriber_ == nullptr) throw std::runtime_error("cannot create publisher/subscriber");
}

DdsParticipant::~DdsParticipant() {
  if (participant_ == nullptr) return;
  participant_->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

Topic* DdsParticipant::topic(const std::string& name, TypeSupport type) {
  if (TopicDescription* existing = participant_->lookup_topicdescription(name))
    return static_cast<Topic*>(existing);
  type.register_type(participant_);
  Topic* topic = participant_->create_topic(name, type.get_type_name(), TOPIC_QOS_DEFAULT);
  if (topic == nullptr) throw std::runtime_error("cannot create topic " + name);
  return topic;
}

}  // namespace scanfilter::dds_io
